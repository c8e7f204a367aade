#include "quadmc/rules/adaptive_cubature.hpp"

#include "quadmc/functions/genz.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <thread>

namespace {

// The Genz Gaussian behind a counter of the points it is asked for, so a test can compare the
// evaluations a run reports with the integrand calls it really made.
class counted_gaussian {
 public:
  counted_gaussian(quadmc::genz_gaussian f, std::shared_ptr<std::atomic<std::uint64_t>> calls)
      : f_(std::move(f)), calls_(std::move(calls)) {}
  std::size_t dimension() const noexcept { return f_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    calls_->fetch_add(y.size());
    f_.evaluate(x, y);
  }
  quadmc::integrand_info info() const { return f_.info(); }

 private:
  quadmc::genz_gaussian f_;
  std::shared_ptr<std::atomic<std::uint64_t>> calls_;
};

quadmc::genz_gaussian gaussian(std::size_t s, std::uint64_t seed) {
  auto p = quadmc::genz_random_parameters(quadmc::genz_family::gaussian, s, seed);
  return quadmc::genz_gaussian(p.a, p.u);
}

// Runs to a tolerance on a smooth integrand: the estimate reaches it, the true error is under
// it too (|Q₇ − Q₅| estimates Q₅'s error and over-estimates Q₇'s on smooth f), and the
// evaluations are 1 + 2k regions' worth, each counted by the integrand itself.
TEST(AdaptiveCubature, ReachesATolerance) {
  for (std::size_t s : {2u, 3u, 5u}) {
    auto calls = std::make_shared<std::atomic<std::uint64_t>>(0);
    const counted_gaussian f(gaussian(s, 40 + s), calls);
    const double exact = f.info().exact;
    const double tolerance = 1e-7 * exact;
    const auto r = quadmc::genz_malik_cubature(
        f, {.max_evaluations = std::uint64_t{1} << 26, .absolute_tolerance = tolerance});
    EXPECT_TRUE(r.converged) << "s = " << s;
    EXPECT_LE(r.error_estimate, tolerance) << "s = " << s;
    EXPECT_LE(std::abs(r.value - exact), tolerance) << "s = " << s;
    const std::uint64_t points = quadmc::genz_malik_rule::points_for(s);
    EXPECT_EQ(r.evaluations, calls->load()) << "s = " << s;
    EXPECT_EQ(r.evaluations % (2 * points), points) << "s = " << s;
    EXPECT_EQ(r.regions, (r.evaluations / points + 1) / 2) << "s = " << s;
  }
}

// A budget is never exceeded, whatever its size relative to a region; one region's points is
// the smallest run: the rule alone.
TEST(AdaptiveCubature, NeverSpendsMoreThanTheBudget) {
  const std::size_t s = 3;
  const std::uint64_t points = quadmc::genz_malik_rule::points_for(s);
  for (std::uint64_t budget : {points, points + 1, 3 * points - 1, 3 * points, 1000ul, 12345ul}) {
    auto calls = std::make_shared<std::atomic<std::uint64_t>>(0);
    const counted_gaussian f(gaussian(s, 7), calls);
    const auto r = quadmc::genz_malik_cubature(f, {.max_evaluations = budget});
    EXPECT_LE(r.evaluations, budget);
    EXPECT_GT(r.evaluations + 2 * points, budget) << "it stops only when a split no longer fits";
    EXPECT_EQ(r.evaluations, calls->load());
    EXPECT_FALSE(r.converged);
  }
}

// Budget control halves the estimate per round, so more budget gives a smaller error; on a smooth
// f the estimate stays above the true error.
TEST(AdaptiveCubature, MoreBudgetGivesSmallerErrors) {
  const quadmc::genz_gaussian f = gaussian(4, 3);
  const double exact = f.info().exact;
  double previous = std::numeric_limits<double>::infinity();
  for (std::uint64_t budget : {10'000ul, 100'000ul, 1'000'000ul}) {
    const auto r = quadmc::genz_malik_cubature(f, {.max_evaluations = budget});
    const double error = std::abs(r.value - exact);
    EXPECT_LT(error, previous) << "budget " << budget;
    EXPECT_LE(error, r.error_estimate) << "budget " << budget;
    previous = error;
  }
}

// Bitwise the same on 1, 2, 3 and 8 threads, in both controls: the threads only evaluate regions,
// every decision and sum is made in one fixed order.
TEST(AdaptiveCubature, IsBitwiseTheSameForAnyThreadCount) {
  for (std::size_t s : {2u, 6u}) {
    const quadmc::genz_gaussian f = gaussian(s, 11);
    for (const double tolerance : {0.0, 1e-9}) {
      const auto one = quadmc::genz_malik_cubature(
          f, {.max_evaluations = 3'000'000, .absolute_tolerance = tolerance, .threads = 1});
      for (unsigned threads : {2u, 3u, 8u}) {
        const auto many = quadmc::genz_malik_cubature(
            f, {.max_evaluations = 3'000'000, .absolute_tolerance = tolerance, .threads = threads});
        EXPECT_EQ(std::bit_cast<std::uint64_t>(one.value), std::bit_cast<std::uint64_t>(many.value))
            << "s = " << s << ", threads " << threads;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(one.error_estimate),
                  std::bit_cast<std::uint64_t>(many.error_estimate));
        EXPECT_EQ(one.evaluations, many.evaluations);
      }
    }
  }
}

// An integrand that integrates another one by genz_malik_cubature on every batch (so a run nested
// in a run, on the same thread) and returns the outer Gaussian's values; it records whether the
// inner run gave the bits it should.
class nesting_gaussian {
 public:
  nesting_gaussian(quadmc::genz_gaussian outer, quadmc::genz_gaussian inner,
                   quadmc::adaptive_cubature_result expected_inner)
      : outer_(std::move(outer)), inner_(std::move(inner)), expected_(expected_inner) {}
  std::size_t dimension() const noexcept { return outer_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const auto r = quadmc::genz_malik_cubature(
        inner_, {.max_evaluations = 100'000, .absolute_tolerance = 1e-6 * inner_.info().exact});
    if (std::bit_cast<std::uint64_t>(r.value) != std::bit_cast<std::uint64_t>(expected_.value) ||
        r.evaluations != expected_.evaluations) {
      *inner_differs_ = true;
    }
    outer_.evaluate(x, y);
  }
  quadmc::integrand_info info() const { return outer_.info(); }
  bool inner_differs() const noexcept { return *inner_differs_; }

 private:
  quadmc::genz_gaussian outer_, inner_;
  quadmc::adaptive_cubature_result expected_;
  std::shared_ptr<bool> inner_differs_ = std::make_shared<bool>(false);
};

// The Genz Gaussian until its `calls`-th batch, which holds a NaN: a run that throws midway.
class failing_gaussian {
 public:
  failing_gaussian(quadmc::genz_gaussian f, int calls)
      : f_(std::move(f)), left_(std::make_shared<int>(calls)) {}
  std::size_t dimension() const noexcept { return f_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    f_.evaluate(x, y);
    if (--*left_ == 0) y[0] = std::numeric_limits<double>::quiet_NaN();
  }
  quadmc::integrand_info info() const { return f_.info(); }

 private:
  quadmc::genz_gaussian f_;
  std::shared_ptr<int> left_;
};

// A thread keeps the storage of its last run for the next (adaptive_cubature.hpp, Memory): a run
// after larger and smaller runs, after a run that threw, and a run nested in another's integrand
// give the bits of the same run on a new thread, which has nothing kept.
TEST(AdaptiveCubature, IsBitwiseTheSameWhateverRanBeforeOnItsThread) {
  using quadmc::genz_malik_cubature;
  const auto same = [](const quadmc::adaptive_cubature_result& a,
                       const quadmc::adaptive_cubature_result& b) {
    return std::bit_cast<std::uint64_t>(a.value) == std::bit_cast<std::uint64_t>(b.value) &&
           std::bit_cast<std::uint64_t>(a.error_estimate) ==
               std::bit_cast<std::uint64_t>(b.error_estimate) &&
           a.evaluations == b.evaluations && a.regions == b.regions;
  };
  for (std::size_t s : {2u, 4u}) {
    const quadmc::genz_gaussian f = gaussian(s, 21);
    const quadmc::adaptive_cubature_options to_tolerance{
        .max_evaluations = 1'000'000, .absolute_tolerance = 1e-6 * f.info().exact};
    quadmc::adaptive_cubature_result fresh;
    std::thread([&] { fresh = genz_malik_cubature(f, to_tolerance); }).join();

    (void)genz_malik_cubature(gaussian(5, 2), {.max_evaluations = 200'000});
    EXPECT_TRUE(same(genz_malik_cubature(f, to_tolerance), fresh)) << "after a larger run";
    (void)genz_malik_cubature(gaussian(3, 2), {.max_evaluations = 100});
    EXPECT_TRUE(same(genz_malik_cubature(f, to_tolerance), fresh)) << "after a smaller run";
    // About 30 000 regions in s = 2: more than the 1 MiB a thread keeps.
    (void)genz_malik_cubature(gaussian(2, 2), {.max_evaluations = 1'000'000});
    EXPECT_TRUE(same(genz_malik_cubature(f, to_tolerance), fresh)) << "after a run beyond 1 MiB";
    EXPECT_THROW((void)genz_malik_cubature(failing_gaussian(gaussian(s, 4), 5),
                                           {.max_evaluations = 1'000'000}),
                 quadmc::non_finite_value);
    EXPECT_TRUE(same(genz_malik_cubature(f, to_tolerance), fresh)) << "after a run that threw";

    const quadmc::genz_gaussian inner = gaussian(3, 5);
    const auto inner_alone = genz_malik_cubature(
        inner, {.max_evaluations = 100'000, .absolute_tolerance = 1e-6 * inner.info().exact});
    const nesting_gaussian nesting(gaussian(s, 21), inner, inner_alone);
    EXPECT_TRUE(same(genz_malik_cubature(nesting, to_tolerance), fresh)) << "nested, s = " << s;
    EXPECT_FALSE(nesting.inner_differs()) << "the inner runs, s = " << s;
  }
}

// A polynomial of degree ≤ 7 is integrated exactly by the first region: the estimate |Q₇ − Q₅|
// of a degree-5 polynomial is rounding only, and the run stops at once under a tolerance.
TEST(AdaptiveCubature, StopsAtOnceWhenTheRuleIsExact) {
  const auto f = [] {
    quadmc::integrand_info info;
    info.name = "cubic";
    info.domain = quadmc::box::unit(3);
    info.exact = 0.25 * 0.5 * 0.5 + 1.0;
    struct cubic {
      quadmc::integrand_info info_;
      std::size_t dimension() const noexcept { return 3; }
      void evaluate(std::span<const double> x, std::span<double> y) const {
        for (std::size_t i = 0; i < y.size(); ++i) {
          y[i] = x[3 * i] * x[3 * i] * x[3 * i] * x[3 * i + 1] * x[3 * i + 2] + 1.0;
        }
      }
      quadmc::integrand_info info() const { return info_; }
    };
    return cubic{info};
  }();
  const auto r =
      quadmc::genz_malik_cubature(f, {.max_evaluations = 100'000, .absolute_tolerance = 1e-12});
  EXPECT_EQ(r.evaluations, quadmc::genz_malik_rule::points_for(3));
  EXPECT_NEAR(r.value, f.info().exact, 1e-14);
  EXPECT_TRUE(r.converged);
}

TEST(AdaptiveCubature, RefusesWhatItCannotRun) {
  const quadmc::genz_gaussian f = gaussian(3, 1);
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::genz_malik_cubature(f, {.max_evaluations = 32}); },
      "at least one region's 2^s + 2s² + 2s + 1 = 33 evaluations"));
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [&] {
        (void)quadmc::genz_malik_cubature(f, {.max_evaluations = 1000, .absolute_tolerance = -1});
      },
      "absolute_tolerance"));
  const quadmc::genz_gaussian line = gaussian(1, 1);
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::genz_malik_cubature(line, {.max_evaluations = 1000}); },
      "between 2 and 40"));
}

}  // namespace
