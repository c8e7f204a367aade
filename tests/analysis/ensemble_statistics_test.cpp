// Tests of ensemble_statistics.hpp: the per-instance MSE summaries on a hand-made ensemble, each
// computed from its definition, and the bad inputs.
#include "quadmc/analysis/ensemble_statistics.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <vector>

namespace {

using namespace quadmc;

std::vector<repetition_result> values_of(const std::vector<double>& v) {
  std::vector<repetition_result> out;
  for (const double x : v) {
    repetition_result r;
    r.value = x;
    out.push_back(r);
  }
  return out;
}

// Four instances of two repetitions against reference 0: errors (1, −1), (2, 0), (0, 0), (3, 3)
// give MSE_k = 1, 2, 0, 9: mean 3, median (1 + 2)/2, worst 9, and Student's interval from their
// sample variance (4 + 1 + 9 + 36)/3, its low end clipped at 0.
TEST(EnsembleStatistics, MeanIntervalMedianAndWorstOfTheInstances) {
  const auto reps = values_of({1, -1, 2, 0, 0, 0, 3, 3});
  const ensemble_statistics e = compute_ensemble_statistics(reps, 0.0, 4);
  EXPECT_EQ(e.instances, 4u);
  EXPECT_DOUBLE_EQ(e.mse_mean, 3.0);
  EXPECT_DOUBLE_EQ(e.mse_median, 1.5);
  EXPECT_DOUBLE_EQ(e.mse_worst, 9.0);
  const double half =
      boost::math::quantile(boost::math::students_t(3.0), 0.975) * std::sqrt(50.0 / 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(e.mse_ci95_high, 3.0 + half);
  EXPECT_EQ(e.mse_ci95_low, 0.0) << "3 − " << half << " < 0";
  // An odd count takes the middle one; one instance has no interval.
  EXPECT_DOUBLE_EQ(compute_ensemble_statistics(values_of({1, 5, 2}), 0.0, 3).mse_median, 4.0);
  const ensemble_statistics one = compute_ensemble_statistics(values_of({2, 4}), 1.0, 1);
  EXPECT_DOUBLE_EQ(one.mse_mean, 5.0);
  EXPECT_TRUE(std::isnan(one.mse_ci95_low));
}

TEST(EnsembleStatistics, BadInputIsNamed) {
  const auto reps = values_of({1, 2, 3});
  EXPECT_THROW(compute_ensemble_statistics(reps, 0.0, 2), invalid_argument);
  EXPECT_THROW(compute_ensemble_statistics(reps, 0.0, 0), invalid_argument);
  EXPECT_THROW(compute_ensemble_statistics({}, 0.0, 1), invalid_argument);
  EXPECT_THROW(compute_ensemble_statistics(reps, std::nan(""), 1), invalid_argument);
}

}  // namespace
