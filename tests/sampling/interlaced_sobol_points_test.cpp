// Tests of interlaced_sobol_points.hpp: the interlacing D_α on digits written out by hand, the
// points against the digits of the αs-dimensional Sobol' points (another code path of
// sobol_points), the one-dimensional net property the interlacing provably keeps, unbiasedness of
// the Owen-scrambled set, bitwise reproducibility for any batch split, outputs in [0, 1), and the
// bad input it refuses. The convergence rates are measured in tests/methods/ (they need a fit).
#include "quadmc/sampling/interlaced_sobol_points.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <span>
#include <string>
#include <vector>

namespace quadmc {
namespace {

static_assert(point_set<interlaced_sobol_points<owen_scramble>>);
static_assert(point_set<interlaced_sobol_points<digital_shift>>);
static_assert(point_set<interlaced_sobol_points<unrandomized_digits>>);

// A fraction whose leading binary digits are `digits` (text of '0' and '1'), as a 64-digit word.
std::uint64_t binary_fraction(const char* digits) {
  std::uint64_t v = 0;
  int bit = 63;
  for (const char* c = digits; *c != '\0'; ++c, --bit) {
    if (*c == '1') v |= std::uint64_t{1} << bit;
  }
  return v;
}

// By hand, from y = Σ_a Σ_i x_{i,a} 2^−(i + (a−1)α) ([Dick 2008]): the digits of the inputs taken
// in turn, first digits first.
TEST(InterlacedSobolPoints, InterlacesKnownDigits) {
  // α = 2: 0.1011₂ and 0.0110₂ → digits 1 0 | 0 1 | 1 1 | 1 0 → 0.10011110₂.
  const std::array<std::uint64_t, 2> two{binary_fraction("1011"), binary_fraction("0110")};
  EXPECT_EQ(interlace_digits(two), binary_fraction("10011110"));
  // α = 3: 0.101₂, 0.011₂, 0.110₂ → 1 0 1 | 0 1 1 | 1 1 0 → 0.101011110₂.
  const std::array<std::uint64_t, 3> three{binary_fraction("101"), binary_fraction("011"),
                                           binary_fraction("110")};
  EXPECT_EQ(interlace_digits(three), binary_fraction("101011110"));
  // α = 1 is the identity.
  const std::array<std::uint64_t, 1> one{binary_fraction("1101")};
  EXPECT_EQ(interlace_digits(one), binary_fraction("1101"));
  // The last digits kept: digit 32 of x_2 is digit 64 of y (α = 2); digit 21 of x_3 is digit 63
  // of y and digit 64 (there is no 22nd digit of x_1 taken) stays 0 (α = 3).
  const std::array<std::uint64_t, 2> last_two{0, std::uint64_t{1} << 32};
  EXPECT_EQ(interlace_digits(last_two), std::uint64_t{1});
  const std::array<std::uint64_t, 3> last_three{0, 0, std::uint64_t{1} << 43};
  EXPECT_EQ(interlace_digits(last_three), std::uint64_t{2});
  const std::array<std::uint64_t, 3> all_ones{~std::uint64_t{0}, ~std::uint64_t{0},
                                              ~std::uint64_t{0}};
  EXPECT_EQ(interlace_digits(all_ones), ~std::uint64_t{1});
  // Digit 22 of x_1 and later are not taken (they would be digit 64 + 1 of y).
  const std::array<std::uint64_t, 3> beyond{std::uint64_t{1} << 42, 0, 0};
  EXPECT_EQ(interlace_digits(beyond), 0u);
}

// The points are the interlaced 64-digit words of the αs-dimensional Sobol' points
// (sobol_points::generate_digits, the scalar walk; the points go through the vector kernel's
// doubles), kept to 53 digits, for every randomization and for s·α up to the whole table.
template <class R>
void expect_points_interlace_the_digits(std::size_t s, unsigned alpha, std::uint64_t n) {
  const interlaced_sobol_points<R> points(s, alpha, n, 11, 3);
  const sobol_points<R> base(s * alpha, n, 11, 3);
  std::vector<double> x(n * s);
  points.generate(0, x);
  std::vector<std::uint64_t> digits(n * s * alpha);
  base.generate_digits(0, digits);
  for (std::uint64_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      const std::span<const std::uint64_t> in(digits.data() + (i * s + j) * alpha, alpha);
      const double expected = fraction_to_unit(interlace_digits(in));
      ASSERT_EQ(x[i * s + j], expected)
          << "s = " << s << ", α = " << alpha << ", point " << i << ", coordinate " << j;
      ASSERT_LT(x[i * s + j], 1.0);
      ASSERT_GE(x[i * s + j], 0.0);
    }
  }
}

TEST(InterlacedSobolPoints, AreTheInterlacedDigitsOfTheSobolPoints) {
  for (const unsigned alpha : {1u, 2u, 3u}) {
    for (const std::size_t s : {1u, 2u, 5u}) {
      expect_points_interlace_the_digits<unrandomized_digits>(s, alpha, 1024);
      expect_points_interlace_the_digits<owen_scramble>(s, alpha, 1024);
      expect_points_interlace_the_digits<digital_shift>(s, alpha, 1024);
    }
  }
  // The largest s for α = 3 (3 · 1222 = 3666 ≤ 3667): one point per chunk of generate().
  expect_points_interlace_the_digits<owen_scramble>(1222, 3, 8);
}

// The smallest t for which the input coordinates a … a + α − 1 of the N = 2^m points x (row-major,
// `stride` per point) are a (t, m, α)-net: every elementary interval Π[c_i 2^−d_i, (c_i+1)2^−d_i)
// with Σd_i = m − t holds 2^t points.
// Calls f(d) for every composition d_1 + … + d_α = total with d_i ≥ 0.
template <class F>
void for_each_digit_split(unsigned alpha, unsigned total, std::array<unsigned, 3>& d, unsigned i,
                          F&& f) {
  if (i + 1 == alpha) {
    d[i] = total;
    f();
    return;
  }
  for (unsigned k = 0; k <= total; ++k) {
    d[i] = k;
    for_each_digit_split(alpha, total - k, d, i + 1, f);
  }
}

unsigned input_t_value(const std::vector<double>& x, std::size_t stride, std::size_t a,
                       unsigned alpha, unsigned m) {
  const std::uint64_t n = std::uint64_t{1} << m;
  for (unsigned t = 0; t <= m; ++t) {
    bool net = true;
    std::array<unsigned, 3> d{};
    for_each_digit_split(alpha, m - t, d, 0, [&] {
      if (!net) return;
      std::vector<std::uint32_t> count(std::size_t{1} << (m - t), 0);
      for (std::uint64_t i = 0; i < n; ++i) {
        std::uint64_t box = 0;
        for (unsigned k = 0; k < alpha; ++k) {
          const auto c =
              static_cast<std::uint64_t>(std::ldexp(x[i * stride + a + k], static_cast<int>(d[k])));
          box = (box << d[k]) | c;
        }
        ++count[box];
      }
      for (const std::uint32_t c : count) net = net && c == (std::uint32_t{1} << t);
    });
    if (net) return t;
  }
  return m;
}

// The 1D net property that interlacing provably keeps. The first m − t digits of y_j are the first
// d_i = ⌈(m − t − i + 1)/α⌉ digits of its inputs i = 1 … α, Σd_i = m − t, so each interval of
// length 2^−(m−t) of y_j is one elementary interval of its α inputs: when those are a (t, m,
// α)-net, y_j is a (t, m, 1)-net, 2^t points in each interval of length 2^−(m−t). Sobol's first two
// dimensions are a (0, m, 2)-net, so y_1 of α = 2 has one point per interval of 2^−m; the t of the
// later inputs is measured on them. The order-α net property itself ([Dick 2008]'s t-value of an
// order-α net) needs the dual net's weights, too costly to check here; this is the part a test can
// count. Every randomization here keeps elementary intervals' counts (sobol_points_test.cpp), so
// the property holds for each.
template <class R>
void expect_one_dimensional_nets(std::size_t s, unsigned alpha, unsigned m) {
  const std::uint64_t n = std::uint64_t{1} << m;
  const interlaced_sobol_points<R> points(s, alpha, n, 5, 1);
  const sobol_points<R> base(s * alpha, n, 5, 1);
  std::vector<double> y(n * s), x(n * s * alpha);
  points.generate(0, y);
  base.generate(0, x);
  for (std::size_t j = 0; j < s; ++j) {
    const unsigned t = input_t_value(x, s * alpha, j * alpha, alpha, m);
    if (j == 0 && alpha == 2) {
      EXPECT_EQ(t, 0u) << "Sobol' dimensions 1 and 2: a (0, m, 2)-net";
    }
    std::vector<std::uint32_t> count(std::size_t{1} << (m - t), 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      ++count[static_cast<std::size_t>(std::ldexp(y[i * s + j], static_cast<int>(m - t)))];
    }
    for (std::size_t c = 0; c < count.size(); ++c) {
      ASSERT_EQ(count[c], std::uint32_t{1} << t)
          << "s = " << s << ", α = " << alpha << ", m = " << m << ", coordinate " << j
          << ", t = " << t << ", interval " << c;
    }
  }
}

TEST(InterlacedSobolPoints, EachCoordinateIsAOneDimensionalNet) {
  for (const unsigned m : {4u, 8u, 11u}) {
    for (const unsigned alpha : {2u, 3u}) {
      expect_one_dimensional_nets<unrandomized_digits>(3, alpha, m);
      expect_one_dimensional_nets<owen_scramble>(3, alpha, m);
      expect_one_dimensional_nets<digital_shift>(3, alpha, m);
    }
  }
}

// Unbiasedness ([Dick 2011]: each scrambled input is uniform, and D_α maps independent uniform
// inputs to a uniform output): the mean over R = 400 independent scramblings of a 64-point
// estimate of ∫ Π(3x_j²) = 1 over [0,1]^2 lies within t(1 − 5e-5, R − 1)·s_R/√R of 1: a false
// alarm of 1e-4 under the t approximation (R = 400 replicates of a bounded estimate). The same
// for the digital shift.
template <class R>
void expect_unbiased(unsigned alpha) {
  constexpr std::size_t s = 2;
  constexpr std::uint64_t n = 64;
  constexpr int replicates = 400;
  std::vector<double> values;
  std::vector<double> x(n * s);
  for (int r = 0; r < replicates; ++r) {
    const interlaced_sobol_points<R> points(s, alpha, n, 77, static_cast<std::uint64_t>(r));
    points.generate(0, x);
    double sum = 0.0;
    for (std::uint64_t i = 0; i < n; ++i) {
      double f = 1.0;
      for (std::size_t j = 0; j < s; ++j) f *= 3.0 * x[i * s + j] * x[i * s + j];
      sum += f;
    }
    values.push_back(sum / static_cast<double>(n));
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / replicates;
  double m2 = 0.0;
  for (double v : values) m2 += (v - mean) * (v - mean);
  const double se = std::sqrt(m2 / (replicates - 1) / replicates);
  const double t = boost::math::quantile(boost::math::students_t(replicates - 1), 1.0 - 5e-5);
  EXPECT_LE(std::abs(mean - 1.0), t * se) << "α = " << alpha << ", mean " << mean << ", se " << se;
  EXPECT_GT(se, 0.0) << "a randomization that changes nothing";
}

TEST(InterlacedSobolPoints, RandomizedEstimatesAreUnbiased) {
  for (const unsigned alpha : {2u, 3u}) {
    expect_unbiased<owen_scramble>(alpha);
    expect_unbiased<digital_shift>(alpha);
  }
}

// (s, N, seed, stream)-pure: batches of any size starting anywhere give the same bits as one
// batch, including batches longer than one chunk of generate() and ones cut inside a block of
// the vector kernel.
TEST(InterlacedSobolPoints, BatchSplitDoesNotChangeAnyBit) {
  for (const std::size_t s : {1u, 3u, 700u}) {
    const std::uint64_t n = s > 100 ? 64 : 4096;
    const interlaced_sobol_points<owen_scramble> points(s, 2, n, 3, 8);
    std::vector<double> whole(n * s), pieces(n * s);
    points.generate(0, whole);
    for (std::uint64_t first = 0, size = 1; first < n; first += size, size = size * 3 + 1) {
      const std::uint64_t count = std::min(size, n - first);
      points.generate(first, std::span<double>(pieces.data() + first * s, count * s));
    }
    EXPECT_EQ(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(double)), 0)
        << "s = " << s;
  }
}

TEST(InterlacedSobolPoints, RejectsWhatItCannotInterlace) {
  EXPECT_THROW(interlaced_sobol_points<owen_scramble>(2, 0, 64, 1, 1), invalid_argument);
  EXPECT_THROW(interlaced_sobol_points<owen_scramble>(2, 4, 64, 1, 1), invalid_argument);
  // α·s ≤ 3667: s = 1834 with α = 2 needs 3668 dimensions.
  EXPECT_NO_THROW(interlaced_sobol_points<owen_scramble>(1833, 2, 4, 1, 1));
  try {
    interlaced_sobol_points<owen_scramble>(1834, 2, 4, 1, 1);
    ADD_FAILURE() << "s = 1834 with α = 2 accepted";
  } catch (const invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("1834"), std::string::npos) << message;
    EXPECT_NE(message.find("3667"), std::string::npos) << message;
    EXPECT_NE(message.find("α = 2"), std::string::npos) << message;
  }
  EXPECT_THROW(interlaced_sobol_points<owen_scramble>(0, 2, 4, 1, 1), invalid_argument);
  EXPECT_THROW(interlaced_sobol_points<owen_scramble>(2, 2, (std::uint64_t{1} << 32) + 1, 1, 1),
               invalid_argument);
}

}  // namespace
}  // namespace quadmc
