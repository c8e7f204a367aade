// sample_values (estimators/sample_values.hpp): each value in its place, on any thread count,
// mapped to f's box and times its volume, and the Gray-code run in natural order.
#include "quadmc/estimators/sample_values.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace quadmc {
namespace {

// f(x) = x₀ on the box [2, 5] × [0, 1]: volume 3.
struct first_coordinate {
  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[2 * i];
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "first_coordinate";
    i.domain = box{{2.0, 0.0}, {5.0, 1.0}};
    i.exact = 10.5;
    return i;
  }
};

TEST(SampleValues, EachValueIsVolumeTimesFAtItsMappedPoint) {
  const independent_points points(2, 40000, 3, 4);
  std::vector<double> y(30000);
  sample_values(first_coordinate{}, points, 5000, y, 1);
  std::vector<double> x(2);
  for (std::size_t i = 0; i < y.size(); i += 997) {
    points.generate(5000 + i, x);
    EXPECT_EQ(y[i], 3.0 * (2.0 + 3.0 * x[0])) << i;
  }
  std::vector<double> threaded(30000);
  sample_values(first_coordinate{}, points, 5000, threaded, 3);
  EXPECT_EQ(y, threaded);
}

TEST(SampleValues, GrayCodeRunsLandInNaturalIndexOrder) {
  const sobol_points<unrandomized_digits> points(2, 64, 1, 1);
  std::vector<double> gray(32);
  std::vector<double> natural(32);
  sample_values(first_coordinate{}, points, 32, gray, 1, false);
  sample_values(first_coordinate{}, points, 32, natural, 1, true);
  for (std::uint64_t p = 32; p < 64; ++p) EXPECT_EQ(natural[(p ^ (p >> 1)) - 32], gray[p - 32]);
  std::vector<double> odd(24);
  EXPECT_THROW(sample_values(first_coordinate{}, points, 32, odd, 1, true), invalid_argument);
}

}  // namespace
}  // namespace quadmc
