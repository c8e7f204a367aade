#include "quadmc/sampling/rejection_disk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace quadmc;

// Each trial is accepted with probability p = π/4, independently; over T trials the acceptance
// rate has standard deviation √(p(1−p)/T). 4.5 of them: false alarm ≈ 7e-6 (normal approx.).
TEST(RejectionDisk, AcceptanceRateIsPiOverFour) {
  const auto r = rejection_sample_disk(1000000, 1, 1);
  const double p = std::numbers::pi / 4.0;
  const double sd = std::sqrt(p * (1 - p) / double(r.trials));
  EXPECT_NEAR(r.acceptance_rate(), p, 4.5 * sd) << "trials " << r.trials;
  EXPECT_EQ(r.points.size(), 2000000u);
}

// Accepted points lie in the disk, and the fraction inside the radius-½ disk is ¼ (uniform):
// binomial standard deviation √(¼·¾/N), tolerance 4.5 of them (false alarm ≈ 7e-6).
TEST(RejectionDisk, PointsAreUniformInTheDisk) {
  const std::uint64_t n = 1000000;
  const auto r = rejection_sample_disk(n, 2, 1);
  double inner = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double r2 = r.points[2 * i] * r.points[2 * i] + r.points[2 * i + 1] * r.points[2 * i + 1];
    ASSERT_LT(r2, 1.0);
    inner += r2 < 0.25;
  }
  EXPECT_NEAR(inner / double(n), 0.25, 4.5 * std::sqrt(0.25 * 0.75 / double(n)));
}

TEST(RejectionDisk, IsReproducibleAndRejectsZeroPoints) {
  EXPECT_EQ(rejection_sample_disk(100, 3, 4).points, rejection_sample_disk(100, 3, 4).points);
  EXPECT_THROW(rejection_sample_disk(0, 1, 1), invalid_argument);
}

}  // namespace
