// The kernel every Monte Carlo estimator of this library runs: the mean of Y over a point set,
// computed in fixed chunks in parallel, with the error estimate the point set allows.
//
// Use it to write an estimator: give it a point set and a batch function that turns a batch of
// points of [0,1)^s into values Y (f mapped to a box times its volume, f/p for importance
// sampling, a radiance estimate for rendering). Not for deterministic rules (rules/).
//
// Why it looks like this (docs/design.md#hot-path-contract):
//  - Chunks of sample_chunk_points = 12288 points (48 batches of 256, core/batching.hpp),
//    boundaries a function of N and the point set only, folded in chunk order by
//    quadmc::parallel_reduce: bitwise identical results for any thread count. 12288 is a multiple
//    of 3 so the triples of stratum_differences never straddle a chunk; for m points per stratum
//    a chunk is a whole number of strata (m·⌊12288/m⌋ points). The chunk-and-batch loop is the
//    one the rule kernel runs (for_each_batch); the statistics are this kernel's own.
//  - Statistics per batch of 256 values, then merged: the batch sum and the batch's Σ(y − ȳ)² by
//    two passes (each with four interleaved partial sums, a fixed order the compiler can keep in
//    vector registers), merged into the chunk by the formula of [Chan, Golub & LeVeque]
//    (core/welford.hpp); the batch sums are added with Neumaier summation, so the value's rounding
//    error stays at the batch level (about 65ε·mean|Y| for 4 lanes of 64 terms,
//    [Higham 2002, §4.2]) and does not grow with N (Boost's naive_monte_carlo explains why a plain
//    running sum's εN error eventually exceeds σ/√N). Per-sample Welford updates cost a division
//    each; this costs none.
//  - Buffers are allocated once per chunk; the batch function runs once per 256 points, called
//    through a function_ref (core/function_ref.hpp) from the kernel, which is compiled once
//    (lib/src/estimators/sample_mean.cpp) rather than once per point set and estimator.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/function_ref.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/core/welford.hpp"
#include "quadmc/estimators/estimate.hpp"
#include "quadmc/sampling/point_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

// Running statistics of the values Y of one chunk (or of several chunks merged in order).
class sample_statistics {
 public:
  explicit sample_statistics(variance_structure structure = {}) : structure_(structure) {}

  // Y of points first, first + 1, …; within a chunk, batches arrive in index order and groups
  // start aligned.
  void add_batch(std::uint64_t first, std::span<const double> y) noexcept {
    const double sum = four_lane_sum(y, [](double v) { return v; });
    const double mean = sum / static_cast<double>(y.size());
    const double m2 = four_lane_sum(y, [mean](double v) { return (v - mean) * (v - mean); });
    sum_.add(sum);
    all_.merge(welford(y.size(), mean, m2));
    switch (structure_.kind) {
      case variance_kind::within_strata:
        for (const double v : y) add_within_strata(v);
        break;
      case variance_kind::stratum_differences:
        add_stratum_differences(first, y);
        break;
      default:
        break;
    }
  }

  void merge(const sample_statistics& other) noexcept {
    sum_.merge(other.sum_);
    all_.merge(other.all_);
    group_sum_.merge(other.group_sum_);
    groups_ += other.groups_;
  }

  // The estimate of the mean of Y and of its standard error (see variance_kind for each case).
  // `variance` is the per-point variance V̂[Y]_eff = N·std_error², so that std_error =
  // √(variance/N) holds for every point set and the Chebyshev interval can use it.
  estimate result() const noexcept {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const std::uint64_t n = all_.count();
    const double nd = static_cast<double>(n);
    estimate e;
    e.evaluations = n;
    e.value = sum_.value() / nd;
    double variance_of_mean = nan;
    switch (structure_.kind) {
      case variance_kind::independent:
      case variance_kind::independent_bound:
        variance_of_mean = all_.variance() / nd;
        break;
      case variance_kind::within_strata: {
        // Σ vᵢ²σ̂ᵢ²/nᵢ with vᵢ = 1/K, nᵢ = m: Σσ̂ᵢ²/(K²m).
        const double strata = static_cast<double>(groups_);
        variance_of_mean =
            groups_ == 0
                ? nan
                : group_sum_.value() / (strata * strata * static_cast<double>(structure_.group));
        break;
      }
      case variance_kind::stratum_differences:
        // (1/N²)Σσᵢ² with σᵢ² estimated by the mean of the second differences.
        variance_of_mean =
            groups_ == 0 ? nan : group_sum_.value() / static_cast<double>(groups_) / nd;
        break;
      case variance_kind::not_estimable:
        break;
    }
    e.std_error = std::sqrt(variance_of_mean);
    e.variance = variance_of_mean * nd;
    return e;
  }

 private:
  // One value into the per-stratum Welford accumulator; a finished stratum adds its variance.
  // Strata are whole within a chunk, so the count alone says where a stratum ends.
  void add_within_strata(double y) noexcept {
    stratum_.add(y);
    if (stratum_.count() == structure_.group) {
      group_sum_.add(stratum_.variance());
      ++groups_;
      stratum_ = welford{};
    }
  }

  // Consecutive points in triples (index ≡ 0, 1, 2 mod 3); a triple counts when it lies in one
  // row of `group` strata along the last axis, i.e. its last point is at row position ≥ 2.
  // Positions advance by counters: one division per batch, not per point.
  void add_stratum_differences(std::uint64_t first, std::span<const double> y) noexcept {
    const std::uint64_t row = structure_.group;
    // The batch's Σd² goes into four_lanes (the k-th counted triple of the batch into lane
    // k mod 4), added to the Neumaier total once per batch: four independent additions per step
    // where one serial sum was latency-bound (bench/peers/profile_notes.md). A lane holds at most
    // 22 of a batch's ≤ 86 terms, so the error is ≤ 24ε relative, far below the variance
    // estimate's own sampling error. Locals, not members, inside the loop: stores to a member
    // double could alias y, which would force a reload per point.
    std::uint64_t position = first % 3;
    std::uint64_t in_row = first % row;
    double triple[3] = {triple_[0], triple_[1], triple_[2]};
    four_lanes sum;
    std::uint64_t triples = 0;
    std::size_t i = 0;
    // A triple begun in the previous batch: its last one or two points, one at a time.
    for (; position != 0 && i < y.size(); ++i) {
      triple[position] = y[i];
      if (position == 2 && in_row >= 2) {
        sum.add_run(triple, 1);
        ++triples;
      }
      position = position == 2 ? 0 : position + 1;
      in_row = in_row + 1 == row ? 0 : in_row + 1;
    }
    // Whole triples. With row ≥ 3, the triple whose first point has row position q counts iff
    // q ≤ row − 3 (the same test as the last point's position ≥ 2): the counted triples come in
    // runs of ⌊(row − 3 − q)/3⌋ + 1, each run one call of add_run, and between two runs lies at
    // most one triple across a row boundary (q ∈ {row − 2, row − 1}). The triples are counted in
    // the order of the point-by-point loop above, so each lands in the same lane as there. Rows
    // shorter than 3 hold no triple.
    if (row >= 3) {
      const std::uint64_t last_start = row - 3;
      while (i + 3 <= y.size()) {
        if (in_row <= last_start) {
          const std::size_t run = static_cast<std::size_t>(
              std::min<std::uint64_t>((last_start - in_row) / 3 + 1, (y.size() - i) / 3));
          sum.add_run(y.data() + i, run);
          i += 3 * run;
          triples += run;
          in_row += 3 * run;
        } else {
          i += 3;
          in_row += 3;
        }
        if (in_row >= row) in_row -= row;  // in_row ≤ row + 2 < 2·row
      }
    } else {
      i += (y.size() - i) / 3 * 3;
    }
    // A triple that the next batch finishes: its first one or two points.
    for (std::size_t p = 0; i < y.size(); ++i, ++p) triple[p] = y[i];
    for (int k = 0; k < 3; ++k) triple_[k] = triple[k];
    groups_ += triples;
    group_sum_.add(sum.total() / 6.0);
  }

  // Σd² of second differences d = y₀ − 2y₁ + y₂ over consecutive triples, the k-th term added
  // into lane k mod 4 and the lanes combined as (l₀ + l₁) + (l₂ + l₃): the same order on every
  // machine and instruction set. The lanes are kept rotated (lane_[j] is lane (k + j) mod 4), so
  // a run adds four terms per step with constant indices (registers, no stores) and rotates once
  // at its end.
  class four_lanes {
   public:
    // The terms of `run` consecutive triples starting at y (y[3t], y[3t + 1], y[3t + 2]).
    void add_run(const double* y, std::size_t run) noexcept {
      std::size_t t = 0;
      for (; t + 4 <= run; t += 4, y += 12) {
        lane_[0] += square_difference(y);
        lane_[1] += square_difference(y + 3);
        lane_[2] += square_difference(y + 6);
        lane_[3] += square_difference(y + 9);
      }
      switch (run - t) {
        case 3:
          lane_[0] += square_difference(y);
          lane_[1] += square_difference(y + 3);
          lane_[2] += square_difference(y + 6);
          rotate(3);
          break;
        case 2:
          lane_[0] += square_difference(y);
          lane_[1] += square_difference(y + 3);
          rotate(2);
          break;
        case 1:
          lane_[0] += square_difference(y);
          rotate(1);
          break;
        default:
          break;
      }
      terms_ += run;
    }

    double total() const noexcept {
      // Lane m is lane_[(m − k) mod 4] with k = terms_ mod 4; constant indices in every case
      // keep lane_ in registers.
      const double* l = lane_;
      switch (terms_ % 4) {
        case 1:
          return (l[3] + l[0]) + (l[1] + l[2]);
        case 2:
          return (l[2] + l[3]) + (l[0] + l[1]);
        case 3:
          return (l[1] + l[2]) + (l[3] + l[0]);
        default:
          return (l[0] + l[1]) + (l[2] + l[3]);
      }
    }

   private:
    static double square_difference(const double* y) noexcept {
      const double d = y[0] - 2.0 * y[1] + y[2];
      return d * d;
    }

    // lane_[j] ← lane_[(j + r) mod 4]: the lane that receives the next term moves to the front.
    void rotate(std::size_t r) noexcept {
      const double l[4] = {lane_[0], lane_[1], lane_[2], lane_[3]};
      for (std::size_t j = 0; j < 4; ++j) lane_[j] = l[(j + r) % 4];
    }

    double lane_[4] = {0.0, 0.0, 0.0, 0.0};
    std::size_t terms_ = 0;
  };

  // Σ g(y) with four interleaved partial sums combined as (s₀ + s₁) + (s₂ + s₃): the same order
  // on every machine and instruction set, and four independent additions per step.
  template <class G>
  static double four_lane_sum(std::span<const double> y, G g) noexcept {
    double lane[4] = {0.0, 0.0, 0.0, 0.0};
    std::size_t i = 0;
    for (; i + 4 <= y.size(); i += 4) {
      for (std::size_t l = 0; l < 4; ++l) lane[l] += g(y[i + l]);
    }
    for (std::size_t l = 0; i < y.size(); ++i, ++l) lane[l] += g(y[i]);
    return (lane[0] + lane[1]) + (lane[2] + lane[3]);
  }

  variance_structure structure_;
  neumaier_sum sum_;
  welford all_;
  neumaier_sum group_sum_;
  std::uint64_t groups_ = 0;
  welford stratum_;
  double triple_[3] = {0.0, 0.0, 0.0};
};

// sample_mean's chunks return their statistics and write nothing else (batch_values writes only
// its own y), so a cell split across processes may share them (core/chunk_exchange.hpp).
template <>
inline constexpr bool shareable_chunk_result<sample_statistics> = true;

namespace detail {

// Writes points first … first + k − 1 of the set into u (row-major, k·s): called once per batch
// of batch_points points, so that the chunked, parallel kernel below is compiled once, in the
// library, while the set's generate() stays inlined into the caller (as in
// rules/weighted_sum.hpp, batch_source; docs/design.md, "Build time").
using sample_point_source = function_ref<void(std::uint64_t first, std::span<double> u)>;

// Writes the values Y at k generated points u into y: called once per block of
// evaluation_block_points(block) points (core/batching.hpp), one batch unless the integrand asks
// for more per call.
using sample_value_source =
    function_ref<void(std::uint64_t first, std::span<double> u, std::span<double> y)>;

// The kernel proper: the mean of Y over n points of dimension s, chunked for `structure`'s
// groups, folded in chunk order, the statistics per batch whatever the block
// (lib/src/estimators/sample_mean.cpp).
estimate sample_mean_of_batches(std::uint64_t n, std::size_t s, variance_structure structure,
                                unsigned threads, std::size_t block,
                                sample_point_source make_points, sample_value_source make_values);

}  // namespace detail

// Mean of Y over `points`. batch_values(first, u, y) receives a batch of points u (row-major,
// y.size() points starting at index `first`) and writes Y for each into y; it may overwrite u
// (e.g. map it to a box in place). It must be safe to call concurrently (it is called from several
// threads on distinct chunks). `block` is the points per call of batch_values an integrand asks
// for (integrand_info::evaluation_block; 0 = one batch): the points are still generated and the
// statistics still taken per batch, so the result's bits do not depend on it as long as
// batch_values computes each Y from its own point.
template <point_set P, class BatchValues>
estimate sample_mean(const P& points, unsigned threads, BatchValues&& batch_values,
                     std::size_t block = 0) {
  const auto generate = [&points](std::uint64_t first, std::span<double> u) {
    points.generate(first, u);
  };
  return detail::sample_mean_of_batches(points.size(), points.dimension(), points.variance(),
                                        threads, block, detail::sample_point_source(generate),
                                        detail::sample_value_source(batch_values));
}

}  // namespace quadmc
