#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using quadmc::independent_points;

// The coordinates are the stream's uniforms in order: point i, coordinate j = uniform(i·s + j).
TEST(IndependentPoints, CoordinateJOfPointIIsUniformNumberIsPlusJ) {
  const independent_points p(3, 100, 9, 4);
  const quadmc::random_stream rng(9, 4);
  std::vector<double> x(300);
  p.generate(0, x);
  for (std::size_t k = 0; k < x.size(); ++k) ASSERT_EQ(x[k], rng.uniform(k));
}

// Mean and variance of 10^5 uniforms: mean 1/2 ± 4.5·√(1/12/N) (false alarm ≈ 7e-6 by the CLT).
TEST(IndependentPoints, CoordinatesAreUniform) {
  const std::uint64_t n = 100000;
  const independent_points p(1, n, 1, 1);
  std::vector<double> x(n);
  p.generate(0, x);
  double sum = 0.0;
  for (double v : x) sum += v;
  EXPECT_NEAR(sum / double(n), 0.5, 4.5 * std::sqrt(1.0 / 12.0 / double(n)));
}

}  // namespace
