// Test-only: the rule kernel's summation order written out point by point, to compare the real
// kernel (weighted_sum.hpp, tensor_product.hpp) with bit for bit.
//
// It is the order the dedicated tensor-product kernel had before weighted_sum replaced it, and
// that the stress scene's accumulator curves were measured with: point p's node comes from
// point_at(p) alone (no odometer, no tables), x_j = a_j + (b_j − a_j)·t_j, f is called on the
// same batches (256 points from the start of each chunk of 2^14 — an integrand's vector path may
// round a lane differently from its scalar tail, so the batches must match), term = w·f, and
//  - pairwise: per batch pairwise_sum, added to a Neumaier sum per chunk, chunks merged in order;
//  - neumaier: every term into the chunk's Neumaier sum, chunks merged in order;
//  - long_double: every term into the chunk's long double, chunk sums added in order;
//  - naive: one double over all terms left to right;
// times the box volume. The chunk and batch sizes are literals here, not the library's
// constants: a change of the batch size or of any node, weight or order shows as a change of bits
// (checked by hand with a batch of 200 and a reversed weight product); a change of the chunk
// size alone rarely does, because merging compensated or long double chunk sums is nearly exact.
#pragma once

#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc::testing {

// The four accumulators the kernel offers, for the tests that compare each with the reference.
inline constexpr summation all_accumulators[] = {summation::pairwise, summation::neumaier,
                                                 summation::naive, summation::long_double};

// point_at(p, t, w) writes the unit-cube node of point p into t (s values) and its weight into w.
template <class F, class PointAt>
double reference_weighted_sum(const F& f, std::uint64_t total, const PointAt& point_at,
                              summation accumulate) {
  constexpr std::uint64_t chunk = 16384;
  constexpr std::uint64_t batch = 256;
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  std::vector<double> width(s);
  for (std::size_t j = 0; j < s; ++j) width[j] = info.domain.upper[j] - info.domain.lower[j];

  neumaier_sum compensated_total;
  long double long_total = 0.0L;
  double naive_total = 0.0;
  std::vector<double> t(s);
  for (std::uint64_t chunk_begin = 0; chunk_begin < total; chunk_begin += chunk) {
    const std::uint64_t chunk_end = std::min(chunk_begin + chunk, total);
    neumaier_sum part;
    long double long_part = 0.0L;
    for (std::uint64_t first = chunk_begin; first < chunk_end; first += batch) {
      const auto count = static_cast<std::size_t>(std::min(batch, chunk_end - first));
      std::vector<double> x(count * s);
      std::vector<double> w(count);
      std::vector<double> y(count);
      for (std::size_t i = 0; i < count; ++i) {
        point_at(first + i, std::span<double>(t), w[i]);
        for (std::size_t j = 0; j < s; ++j) {
          x[i * s + j] = info.domain.lower[j] + width[j] * t[j];
        }
      }
      f.evaluate(std::span<const double>(x), std::span<double>(y));
      std::vector<double> terms(count);
      for (std::size_t i = 0; i < count; ++i) terms[i] = w[i] * y[i];
      switch (accumulate) {
        case summation::pairwise:
          part.add(pairwise_sum(terms));
          break;
        case summation::neumaier:
          for (const double term : terms) part.add(term);
          break;
        case summation::long_double:
          for (const double term : terms) long_part += static_cast<long double>(term);
          break;
        case summation::naive:
          for (const double term : terms) naive_total += term;
          break;
      }
    }
    compensated_total.merge(part);
    long_total += long_part;
  }
  double sum = 0.0;
  switch (accumulate) {
    case summation::pairwise:
    case summation::neumaier:
      sum = compensated_total.value();
      break;
    case summation::long_double:
      sum = static_cast<double>(long_total);
      break;
    case summation::naive:
      sum = naive_total;
      break;
  }
  return info.domain.volume() * sum;
}

}  // namespace quadmc::testing
