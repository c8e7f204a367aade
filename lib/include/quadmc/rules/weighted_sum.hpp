// The one kernel of every deterministic rule of this layer: Q(f) = vol(box)·Σ_{i<N} w_i f(x_i)
// over a weighted point set (weighted_point_set.hpp), x_i its unit-cube nodes mapped to the
// integrand's box.
//
// Use it to integrate with any weighted point set — a tensor grid (integrate() in
// tensor_product.hpp is weighted_sum over tensor_product_grid), a rule with weights of both signs,
// a QMC rule with weights 1/N. Not for Monte Carlo estimators, which need an error estimate from
// the points (estimators/sample_mean.hpp), and not for adaptive rules (romberg.hpp).
//
// How it runs (the same chunks and batches as before the kernel was shared, so the same bits):
//  - points go to the integrand in batches of batch_points = 256 (row-major x[i*s + j]; one
//    virtual call per batch through any_integrand); each batch's terms w_i·f_i are summed
//    pairwise and batches are added with Neumaier's compensated sum, so the rounding error stays
//    O(ε·Σ|w f|) for any N (core/summation.hpp);
//  - chunks of rule_chunk_points = 2^14 points are the unit of parallel work; their boundaries
//    depend only on N, and parallel_reduce folds them in chunk order, so any thread count gives
//    the same bits (core/batching.hpp);
//  - every batch is checked for NaN/±inf (check_finite_batch), the error naming the point in box
//    coordinates;
//  - the default sum forms w_i·f_i inside its pairwise pass (detail::weighted_pairwise_sum, a
//    vector kernel), bitwise what multiplying first and summing after gives;
//  - the sum can instead be naive, all-Neumaier or long double (enum summation), so the stress
//    scene can show what each accumulator's rounding floor is on the same terms;
//  - no allocation or virtual call per point: buffers once per chunk; per batch, one call through
//    a function pointer (detail::batch_source) into the caller's code, where the set's
//    generate() and the integrand's evaluate() are template calls, inlined. The rest of the
//    kernel is compiled once, in lib/src/rules/weighted_sum.cpp.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/function_ref.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/rule_result.hpp"
#include "quadmc/rules/weighted_point_set.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

// Checks a box for a rule: finite bounds, lower ≤ upper (a reversed axis is rejected, not read
// as a sign flip), finite widths.
inline void require_integration_box(const box& domain) {
  require(domain.upper.size() == domain.lower.size(), "domain.upper size", domain.upper.size(),
          fmt::format("the size of domain.lower, {}", domain.lower.size()));
  for (std::size_t j = 0; j < domain.lower.size(); ++j) {
    const double a = domain.lower[j];
    const double b = domain.upper[j];
    require_finite(a, fmt::format("domain.lower[{}]", j));
    require_finite(b, fmt::format("domain.upper[{}]", j));
    require(a <= b, fmt::format("domain.upper[{}]", j), b,
            fmt::format("≥ domain.lower[{}] = {} (a reversed interval is not integrated with a "
                        "minus sign; swap the bounds)",
                        j, quote(a)));
    require(std::isfinite(b - a), fmt::format("domain width upper[{0}] − lower[{0}]", j), b - a,
            "a finite number (the bounds are too far apart for double)");
  }
}

namespace detail {

// pairwise_sum (core/summation.hpp) of the products w_i·y_i, bitwise: the same split, the same
// eight accumulators per leaf, each product rounded before it is added (never a fused
// multiply-add). One pass instead of a multiply pass and a sum pass, the leaves vector code
// chosen at run time (lib/src/rules/weighted_row_sum*.cpp; docs/design.md#hot-path-contract).
// w and y have the same size.
double weighted_pairwise_sum(std::span<const double> w, std::span<const double> y) noexcept;

// The integrand's info after the checks every rule needs: s ≥ 1, a domain of dimension s, a
// finite box with lower ≤ upper.
template <integrand F>
integrand_info checked_integrand_info(const F& f) {
  integrand_info info = f.info();
  const std::size_t s = f.dimension();
  require(s >= 1, "integrand dimension s", s, "at least 1");
  require(info.domain.dimension() == s, "integrand domain dimension", info.domain.dimension(),
          fmt::format("the integrand's dimension {}", s));
  require_integration_box(info.domain);
  return info;
}

// A weighted point set that also writes elsewhere while it generates (the Smolyak method tallies
// Σ|w| per chunk, methods/sparse_grids.cpp) says so with `static constexpr bool
// writes_on_the_side = true`: a chunk's sum is then not all that the chunk computes, so a cell
// split across processes runs its chunks on every process (core/chunk_exchange.hpp).
template <class P>
concept writes_on_the_side = requires {
  requires P::writes_on_the_side;
};

// Whether the sum with `accumulate` may be split between processes (core/chunk_exchange.hpp):
// the accumulators' own declarations (shareable_chunk_result, lib/src/rules/weighted_sum.cpp) for
// the parallel_reduce ones; the naive sum, one running double carried through the chunks in
// order, by split_naive_sum, which keeps its bits.
bool accumulator_shares_chunks(summation accumulate) noexcept;

// Writes the nodes of points first … first + k − 1 in box coordinates into x (row-major, k·s)
// and their weights into w: called once per batch of batch_points points, so that the kernel
// below is compiled once, in the library, while the set's generate() stays inlined into the
// caller's batch, where the work per point is. (As one template per integrand and set, its four
// accumulators, parallel_reduce and the naive split were instantiated again for each and were
// most of the build time of a file that integrates: docs/design.md, "Build time".)
using batch_source =
    function_ref<void(std::uint64_t first, std::span<double> x, std::span<double> w)>;

// Writes f at k nodes x into y: called once per block of evaluation_block_points(
// info.evaluation_block) points (core/batching.hpp), one batch unless the integrand asks for
// more per call.
using value_source = function_ref<void(std::span<const double> x, std::span<double> y)>;

// The kernel proper, on a checked integrand's info and `total` points made batch by batch by
// `make_batch` and evaluated block by block by `make_values`: vol(box)·Σ w_i f(x_i), each block
// checked finite (the error names info.name and the point), the sums per batch whatever the
// block. share_chunks: whether a chunk's sum is all it computes (see writes_on_the_side).
rule_result weighted_sum_of_batches(const integrand_info& info, std::uint64_t total,
                                    batch_source make_batch, value_source make_values,
                                    bool share_chunks, unsigned threads, summation accumulate);

// The kernel on a checked integrand and a set of its dimension: generate(first, x, w) writes a
// batch of box coordinates and weights. ShareChunks: whether a chunk's sum is all it computes.
template <bool ShareChunks, integrand F, class Generate>
rule_result weighted_sum_of_batches(const F& f, const integrand_info& info, std::uint64_t total,
                                    const Generate& generate, unsigned threads,
                                    summation accumulate) {
  const auto values = [&f](std::span<const double> x, std::span<double> y) { f.evaluate(x, y); };
  return weighted_sum_of_batches(info, total, batch_source(generate), value_source(values),
                                 ShareChunks, threads, accumulate);
}

// weighted_sum after the integrand's checks: checks the set against it and picks the set's own
// map to the box where it has one (box_mapped_point_set), else maps each batch here.
template <integrand F, weighted_point_set P>
rule_result checked_weighted_sum(const F& f, const integrand_info& info, const P& points,
                                 unsigned threads, summation accumulate) {
  const std::size_t s = info.dimension();
  require(points.dimension() == s, "weighted point set dimension", points.dimension(),
          fmt::format("the integrand's dimension {}", s));
  const std::uint64_t total = points.size();
  require(total >= 1, "weighted point set size N", total, "at least 1 point");
  const cube_to_box map(info.domain);
  if constexpr (box_mapped_point_set<P>) {
    const auto on_box = points.mapped(map);
    return weighted_sum_of_batches<!writes_on_the_side<P>>(
        f, info, total,
        [&on_box](std::uint64_t first, std::span<double> x, std::span<double> w) {
          on_box.generate(first, x, w);
        },
        threads, accumulate);
  } else {
    return weighted_sum_of_batches<!writes_on_the_side<P>>(
        f, info, total,
        [&points, &map](std::uint64_t first, std::span<double> x, std::span<double> w) {
          points.generate(first, x, w);
          map.apply(x);
        },
        threads, accumulate);
  }
}

}  // namespace detail

// Whether weighted_sum over a set of type P with `accumulate` shares its chunk results between
// the processes of an active chunk_exchange (core/chunk_exchange.hpp): the facts its kernel
// branches on, the set's writes_on_the_side and the accumulator's declaration. The methods
// layer's shares_chunks (methods/method.hpp) asks this.
template <class P>
bool weighted_sum_shares_chunks(summation accumulate) noexcept {
  return !detail::writes_on_the_side<P> && detail::accumulator_shares_chunks(accumulate);
}

// ∫ f over f.info().domain by the rule `points`: vol(box)·Σ w_i f(x_i), x_i the set's nodes
// mapped to the box. threads = 0 uses every core; the result is bitwise the same for every thread
// count. `accumulate` chooses how the N terms w·f are summed (core/summation.hpp, enum
// summation); the default is pairwise per batch, Neumaier across batches. summation::naive runs
// on one thread whatever `threads` says (a left-to-right sum is one chain of adds); under a
// chunk_exchange its processes share it, with the same bits (core/split_naive_sum.hpp).
// Throws invalid_argument for a bad integrand dimension or domain, a set of another dimension or
// with no points; non_finite_value if f returns NaN/±inf (the message names the point).
// error_estimate is NaN: a fixed rule has no a-posteriori estimate.
template <integrand F, weighted_point_set P>
rule_result weighted_sum(const F& f, const P& points, unsigned threads = 1,
                         summation accumulate = summation::pairwise) {
  const integrand_info info = detail::checked_integrand_info(f);
  return detail::checked_weighted_sum(f, info, points, threads, accumulate);
}

}  // namespace quadmc
