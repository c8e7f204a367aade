#include "quadmc/estimators/sample_mean.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/summation.hpp"

#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

// Y = x₀ + x₁²: any deterministic function of the point will do.
auto values = [](std::uint64_t, std::span<double> u, std::span<double> y) {
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = u[2 * i] + u[2 * i + 1] * u[2 * i + 1];
};

bool bitwise_equal(const estimate& a, const estimate& b) {
  return std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
         std::memcmp(&a.std_error, &b.std_error, sizeof(double)) == 0 &&
         std::memcmp(&a.variance, &b.variance, sizeof(double)) == 0 &&
         a.evaluations == b.evaluations;
}

// 100 003 points = 9 chunks of 12288 and a partial one: any thread count folds them in order.
TEST(SampleMean, IsBitwiseIdenticalForAnyThreadCount) {
  const independent_points p(2, 100003, 1, 2);
  const estimate one = sample_mean(p, 1, values);
  for (unsigned t : {2u, 3u, 8u}) {
    const estimate e = sample_mean(p, t, values);
    EXPECT_TRUE(bitwise_equal(one, e)) << t << " threads: " << e.value << " vs " << one.value;
  }
  const jittered_points j(stratum_grid(2, 100), 3, 1, 2);  // 30 000 points, 3 per stratum
  const estimate jone = sample_mean(j, 1, values);
  for (unsigned t : {2u, 3u, 8u}) EXPECT_TRUE(bitwise_equal(jone, sample_mean(j, t, values)));
}

// A block of points per call of the values (integrand_info::evaluation_block, which a Python
// callable asks for): the points are still generated and the statistics still taken per batch of
// 256, so the bits are those of one batch per call, for every variance structure and for a
// chunk that is not whole batches (5 points per stratum: chunks of 12285). And the calls are
// blocks: at most the chunk, and larger than a batch.
TEST(SampleMean, ValuesPerBlockGiveTheBitsOfValuesPerBatch) {
  const independent_points independent(2, 100003, 1, 2);
  const jittered_points three(stratum_grid(2, 100), 3, 1, 2);
  const jittered_points five(stratum_grid(2, 100), 5, 1, 2);
  const jittered_points one(2, 40000, 1, 1);  // one per stratum: stratum differences
  const auto check = [](const auto& points, const std::string& label) {
    std::size_t largest = 0;
    const auto recorded = [&largest](std::uint64_t first, std::span<double> u,
                                     std::span<double> y) {
      largest = std::max(largest, y.size());
      values(first, u, y);
    };
    const estimate per_batch = sample_mean(points, 1, values);
    const estimate per_block = sample_mean(points, 1, recorded, std::size_t{1} << 14);
    EXPECT_TRUE(bitwise_equal(per_batch, per_block))
        << label << ": " << per_block.value << " vs " << per_batch.value;
    EXPECT_GT(largest, batch_points) << label;
    EXPECT_LE(largest, sample_chunk_points) << label;
  };
  check(independent, "independent");
  check(three, "3 per stratum");
  check(five, "5 per stratum");
  check(one, "1 per stratum");
}

// The value is the plain mean, the independent error is √(s²/N).
TEST(SampleMean, IndependentPointsReportTheSampleVariance) {
  const independent_points p(2, 1000, 3, 3);
  std::vector<double> u(2000), y(1000);
  p.generate(0, u);
  values(0, u, y);
  welford w;
  double sum = 0;
  for (double v : y) {
    w.add(v);
    sum += v;
  }
  const estimate e = sample_mean(p, 1, values);
  EXPECT_NEAR(e.value, sum / 1000, 1e-15);
  EXPECT_NEAR(e.variance, w.variance(), 1e-14);
  EXPECT_NEAR(e.std_error, std::sqrt(w.variance() / 1000), 1e-15);
  EXPECT_EQ(e.evaluations, 1000u);
}

// m = 4 points in each of K = 9 strata: V̂[F] = Σσ̂ᵢ²/(K²m), computed here by hand.
TEST(SampleMean, WithinStrataVarianceIsTheStratifiedFormula) {
  const jittered_points p(stratum_grid(2, 3), 4, 5, 5);
  std::vector<double> u(72), y(36);
  p.generate(0, u);
  values(0, u, y);
  double sum_var = 0;
  for (int k = 0; k < 9; ++k) {
    welford w;
    for (int j = 0; j < 4; ++j) w.add(y[4 * k + j]);
    sum_var += w.variance();
  }
  const estimate e = sample_mean(p, 1, values);
  EXPECT_NEAR(e.std_error * e.std_error, sum_var / (81.0 * 4.0), 1e-15);
  EXPECT_NEAR(e.variance, 36 * sum_var / (81.0 * 4.0), 1e-14);
}

// One point per stratum: second differences within rows of k strata. k = 5: triples (0,1,2) of
// each row are used, (3,4,5) straddles rows and is skipped.
TEST(SampleMean, StratumDifferencesUseTriplesInsideARow) {
  const jittered_points p(2, 25, 1, 1);
  std::vector<double> u(50), y(25);
  p.generate(0, u);
  values(0, u, y);
  double sum = 0;
  int triples = 0;
  for (int t = 0; t + 2 < 25; t += 3) {
    if (t % 5 + 2 >= 5) continue;
    const double d = y[t] - 2 * y[t + 1] + y[t + 2];
    sum += d * d / 6;
    ++triples;
  }
  EXPECT_EQ(triples, 5);  // starting at t = 0, 6, 12, 15, 21
  const estimate e = sample_mean(p, 1, values);
  EXPECT_NEAR(e.std_error * e.std_error, sum / triples / 25, 1e-16);
}

// The stratum-difference sum runs in runs of counted triples; it must give the bits of the
// point-at-a-time loop (rebuilt here): Σd² per batch, the k-th counted triple of the batch into
// lane k mod 4 and the lanes combined as (l₀ + l₁) + (l₂ + l₃), each batch's sum / 6 added with
// Neumaier summation, for rows of every length around the triple size and a long one, and
// batches that start at every residue mod 3 (a chunk's batches start at multiples of 256 ≡ 1).
// Checked after every batch, on the variance (no square root to merge neighbouring values): once
// 48 batch sums are added, an ulp of one batch is below an ulp of the total, and a different
// order of addition would go unseen.
TEST(SampleMean, StratumDifferencesEqualThePointAtATimeLoopBitForBit) {
  random_stream rng(3, 7);
  std::vector<double> y(12288);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = rng.uniform(i) * 10.0 - 3.0;
  for (const std::uint64_t row : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 9u, 10u, 1024u}) {
    for (const std::uint64_t start : {std::uint64_t{0}, std::uint64_t{12288}}) {
      for (const std::size_t last_batch : {std::size_t{256}, std::size_t{100}}) {
        const std::size_t total = 47 * 256 + last_batch;
        sample_statistics stats({variance_kind::stratum_differences, row});
        neumaier_sum reference;
        std::uint64_t triples = 0;
        double triple[3] = {0.0, 0.0, 0.0};
        std::size_t mismatches = 0;
        std::string first_mismatch;
        for (std::size_t b = 0; b < total; b += 256) {
          const std::size_t count = std::min<std::size_t>(256, total - b);
          const std::span<const double> batch(y.data() + b, count);
          stats.add_batch(start + b, batch);
          double lane[4] = {0.0, 0.0, 0.0, 0.0};
          std::size_t counted = 0;
          for (std::size_t i = 0; i < count; ++i) {
            const std::uint64_t index = start + b + i;
            triple[index % 3] = batch[i];
            if (index % 3 == 2 && index % row >= 2) {
              const double d = triple[0] - 2.0 * triple[1] + triple[2];
              lane[counted++ % 4] += d * d;
              ++triples;
            }
          }
          reference.add(((lane[0] + lane[1]) + (lane[2] + lane[3])) / 6.0);
          const double n = static_cast<double>(b + count);
          const double expected = reference.value() / static_cast<double>(triples) / n * n;
          const double got = stats.result().variance;
          const bool same = triples == 0 ? std::isnan(got)
                                         : std::bit_cast<std::uint64_t>(got) ==
                                               std::bit_cast<std::uint64_t>(expected);
          if (!same && mismatches++ == 0) {
            first_mismatch = "after batch " + std::to_string(b / 256) + ": " + std::to_string(got) +
                             " vs " + std::to_string(expected);
          }
        }
        EXPECT_EQ(mismatches, 0u) << "row " << row << ", start " << start << ", last batch "
                                  << last_batch << ", first " << first_mismatch;
      }
    }
  }
}

// k < 3: no triple in a row, no estimate; NaN rather than a made-up number.
TEST(SampleMean, TooFewStrataForDifferencesGiveNaN) {
  const jittered_points p(2, 4, 1, 1);
  EXPECT_TRUE(std::isnan(sample_mean(p, 1, values).std_error));
}

}  // namespace
