// A left-to-right sum s_{k+1} = fl(s_k + t_k) computed by the processes of a chunk_exchange
// (core/chunk_exchange.hpp), each adding the terms of its own block of chunks, with the bits of
// one process adding every term in order. It lets the MPI runner split the naive accumulator's
// cells (summation::naive, the stress scene's largest) like any other.
//
// Why the blocks can be added apart (docs/theory.md#splitting-a-naive-sum): in one binade
// [2^e, 2^(e+1)) every double is a multiple of u = 2^(e−52), and while the sums stay in that
// binade, adding terms of the sum's sign from a start shifted by D, a multiple of 2u, gives every
// later sum shifted by exactly D (rounding to a multiple of u, ties to the even one, commutes
// with the shift). So a process adds its block from a provisional start before the true start
// is known, and from a second start one ulp away, so that one of them has the true start's
// parity; when the true start is known, its end is the provisional end + D if the check of
// shifted_block_end proves it. Where it does not (a block that crosses a binade or a sign, a
// start of 0), the block's owner adds its terms again from the true start: slower, same bits.
//
// Per window of naive_chunks_per_rank chunks per process: (1) each process computes its block's
// terms (kept: at most naive_chunks_per_rank chunks, 512 KB for rules, so they stay in L2) and
// per chunk a pairwise sum, and the processes exchange those sums; (2) each adds its block from its
// provisional starts (the window's true start + the chunk sums before its block), and they exchange
// the provisional ends; (3) every process walks the blocks in order from the true start, and a
// block the check cannot place costs one more exchange. Memory is constant in N.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/summation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace quadmc {

// A block's terms added from two provisional starts one ulp apart (provisional_block_run).
struct naive_block_run {
  double start[2] = {std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::quiet_NaN()};
  double end[2] = {std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::quiet_NaN()};
  bool nonnegative = true;  // every term ≥ 0
  bool nonpositive = true;  // every term ≤ 0
};

// Adds `terms` left to right from `estimate` and from its neighbour in the same binade, and
// notes the terms' signs. Nothing where estimate is not a normal number (the check below needs a
// binade): the run then proves nothing.
inline naive_block_run provisional_block_run(double estimate,
                                             std::span<const double> terms) noexcept {
  naive_block_run run;
  if (!std::isnormal(estimate)) return run;
  const double magnitude = std::fabs(estimate);
  double neighbour = std::nextafter(magnitude, std::numeric_limits<double>::infinity());
  if (std::ilogb(neighbour) != std::ilogb(magnitude)) neighbour = std::nextafter(magnitude, 0.0);
  double a = estimate;
  double b = std::copysign(neighbour, estimate);
  run.start[0] = a;
  run.start[1] = b;
  // Two independent chains of adds, and the sign tests beside them: the chain's latency, about
  // 3 cycles an add, leaves the slots for the rest.
  bool negative = false;
  bool positive = false;
  for (const double t : terms) {
    a += t;
    b += t;
    negative |= t < 0.0;
    positive |= t > 0.0;
  }
  run.end[0] = a;
  run.end[1] = b;
  run.nonnegative = !negative;
  run.nonpositive = !positive;
  return run;
}

// The end of the block's left-to-right sum from `start`, if `run` proves it: start normal, the
// terms of its sign, and for the provisional start of start's parity, both chains (the
// provisional one, and the true one = it + D) inside start's binade. Else nothing.
// Proof sketch (magnitudes; the negative case is its mirror image, as rounding to nearest even
// is symmetric): sums only grow, so a chain whose end is below 2^(e+1) stays in the binade, where
// fl(x + t) is x + t rounded to a multiple of u, ties to even; that rounding commutes with a
// shift by D ≡ 0 (mod 2u).
inline std::optional<double> shifted_block_end(const naive_block_run& run, double start) noexcept {
  if (!std::isnormal(start)) return std::nullopt;
  const bool negative = std::signbit(start);
  if (negative ? !run.nonpositive : !run.nonnegative) return std::nullopt;
  const double magnitude = std::fabs(start);
  const int e = std::ilogb(magnitude);
  const double upper = std::ldexp(1.0, e + 1);
  const double two_ulps = std::ldexp(1.0, e - 51);
  for (int k = 0; k < 2; ++k) {
    if (std::signbit(run.start[k]) != negative) continue;
    const double from = std::fabs(run.start[k]);
    const double to = std::fabs(run.end[k]);
    if (!(std::isnormal(from) && std::ilogb(from) == e && to < upper)) continue;
    const double shift = magnitude - from;        // exact: both in [2^e, 2^(e+1)) (Sterbenz)
    const double ulps_halved = shift / two_ulps;  // exact: a power-of-two scaling
    if (ulps_halved != std::trunc(ulps_halved)) continue;  // the other parity
    const double end = to + shift;  // exact below 2^(e+1): a multiple of u in the binade
    if (!(end < upper)) continue;
    return negative ? -end : end;
  }
  return std::nullopt;
}

// Chunks per process per window: the terms a process keeps between the two passes.
inline constexpr std::size_t naive_chunks_per_rank = 4;

// Σ of every chunk's terms left to right from 0.0, bitwise what one process adding them in order
// gives, computed with the processes of `exchange` (size ≥ 2; every one calls this with the
// same layout). chunk_terms(c, out) writes chunk c's terms in order into out (size
// layout.end(c) − layout.begin(c)); it may throw, and the lowest failing chunk's error is thrown
// on every process, as a serial run throws it. `threads` compute this process's chunks.
template <class ChunkTerms>
double split_naive_sum(chunk_exchange& exchange, const chunking& layout, unsigned threads,
                       const ChunkTerms& chunk_terms) {
  // A chunk's pairwise sum: a provisional figure, only the starts' estimates use it.
  struct slot {
    double value;
  };
  const unsigned ranks = exchange.size();
  const unsigned me = exchange.rank();
  const std::size_t chunks = layout.chunks();
  const std::size_t window = naive_chunks_per_rank * ranks;
  std::vector<double> terms(naive_chunks_per_rank * static_cast<std::size_t>(layout.chunk));
  std::vector<slot> summaries(std::min(window, chunks));
  std::vector<naive_block_run> runs(ranks);
  std::vector<std::size_t> first(ranks + 1);
  std::vector<std::size_t> run_bytes(ranks, sizeof(naive_block_run));
  std::vector<std::size_t> end_bytes(ranks, 0);
  double sum = 0.0;
  for (std::size_t begin = 0; begin < chunks; begin += window) {
    const std::size_t count = std::min(window, chunks - begin);
    // The same shares as distributed_window's: rank r has chunks [first[r], first[r + 1]).
    for (unsigned r = 0; r <= ranks; ++r) first[r] = count * r / ranks;
    const std::uint64_t block_begin = layout.begin(begin + first[me]);
    auto summarise = [&](std::size_t c) {
      const std::span<double> out(terms.data() + (layout.begin(c) - block_begin),
                                  layout.end(c) - layout.begin(c));
      chunk_terms(c, out);
      return pairwise_sum(out);
    };
    detail::distributed_window(exchange, summaries.data(), begin, count, threads, summarise);

    double estimate = sum;
    for (std::size_t c = 0; c < first[me]; ++c) estimate += summaries[c].value;
    const std::uint64_t block_end =
        first[me + 1] > first[me] ? layout.end(begin + first[me + 1] - 1) : block_begin;
    const std::span<const double> mine(terms.data(), block_end - block_begin);
    const naive_block_run own = provisional_block_run(estimate, mine);
    (void)exchange.exchange(&own, runs.data(), run_bytes.data(), {});

    for (unsigned r = 0; r < ranks; ++r) {
      if (first[r] == first[r + 1]) continue;
      if (const std::optional<double> end = shifted_block_end(runs[r], sum)) {
        sum = *end;
        continue;
      }
      // Not proven: the owner adds its terms from the true start and sends the end to all.
      double end = sum;
      if (r == me) {
        for (const double t : mine) end += t;
      }
      std::fill(end_bytes.begin(), end_bytes.end(), 0);
      end_bytes[r] = sizeof(double);
      (void)exchange.exchange(&end, &sum, end_bytes.data(), {});
    }
  }
  return sum;
}

}  // namespace quadmc
