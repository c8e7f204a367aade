// How the library's kernels cut N points into chunks and batches: the batch size, the two chunk
// sizes, and the loop over the batches of one chunk that the rule kernel (rules/weighted_sum.hpp)
// and the Monte Carlo kernel (estimators/sample_mean.hpp) share.
//
// Use it to write a kernel that sums over N points in parallel: cut [0, N) into chunks whose
// boundaries depend only on N (never on the thread count), let quadmc::parallel_reduce run them
// and fold them in chunk order, and walk each chunk in batches. Not a tuning knob: every constant
// here fixes where partial sums start and stop, so changing one changes the bits of every result
// (the committed results and the tests that compare bits would move).
//
//  - batch_points = 256: points per call of the integrand (one virtual call through
//    any_integrand per batch, never per point), and the unit of the per-batch statistics (a
//    pairwise or four-lane sum of 256 terms whose rounding error does not grow with N). An
//    integrand may ask for blocks of several batches per call (evaluation_block_points): the
//    sums stay per batch, so the bits do not move.
//  - rule_chunk_points = 2^14 = 64 batches: large enough that thread start-up (tens of µs) is
//    paid back even for a cheap integrand, small enough that 2 cores stay busy on a 100×100×100
//    grid.
//  - sample_chunk_points = 12288 = 48 batches: a multiple of 3, so the triples of the
//    stratum-difference variance estimate (sampling/point_set.hpp) never straddle a chunk.
// The rules need no multiple of 3 and 2^14 is not one; the two stay apart because either kernel
// taking the other's chunk size would move every result it has produced so far.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace quadmc {

inline constexpr std::size_t batch_points = 256;
inline constexpr std::uint64_t rule_chunk_points = std::uint64_t{1} << 14;
inline constexpr std::uint64_t sample_chunk_points = 12288;

static_assert(rule_chunk_points % batch_points == 0, "a rule chunk is whole batches");
static_assert(sample_chunk_points % batch_points == 0, "a sample chunk is whole batches");
static_assert(sample_chunk_points % 3 == 0, "stratum-difference triples stay inside a chunk");

// [0, total) cut into chunks of `chunk` points, the last one possibly partial. Chunk c is
// [c·chunk, min((c + 1)·chunk, total)).
struct chunking {
  std::uint64_t total = 0;
  std::uint64_t chunk = rule_chunk_points;

  std::size_t chunks() const noexcept {
    return static_cast<std::size_t>(total / chunk + (total % chunk != 0));
  }
  std::uint64_t begin(std::size_t c) const noexcept {
    return static_cast<std::uint64_t>(c) * chunk;
  }
  std::uint64_t end(std::size_t c) const noexcept { return std::min(begin(c) + chunk, total); }
};

// Calls batch(first, count) for the batches of chunk c in index order: count = batch_points
// except for the chunk's last batch, which may be shorter. Batches start at begin(c) +
// k·batch_points, so with a chunk that is whole batches every batch starts at a multiple of
// batch_points.
template <class Batch>
void for_each_batch(const chunking& layout, std::size_t c, Batch&& batch) {
  const std::uint64_t end = layout.end(c);
  for (std::uint64_t first = layout.begin(c); first < end; first += batch_points) {
    batch(first, static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, end - first)));
  }
}

// Points per call of the integrand for an integrand that asks for `requested` (integrand_info::
// evaluation_block; 0 for the default): a whole number of batches, at least one. An integrand
// whose every call costs microseconds (a Python callable) asks for thousands of points per call;
// the library's own integrands take one batch, whose points stay in L1.
constexpr std::size_t evaluation_block_points(std::size_t requested) noexcept {
  return requested <= batch_points ? batch_points : requested / batch_points * batch_points;
}

// Calls block(first, count) for the blocks of `block_points` points (a multiple of batch_points,
// evaluation_block_points) of chunk c in index order, the chunk's last block possibly shorter.
// A block is whole batches of for_each_batch followed by its batches' rest: walking a block with
// for_each_batch_of gives exactly for_each_batch's batches, so a kernel that evaluates f per
// block and sums per batch adds the same batches in the same order, whatever the block size.
template <class Block>
void for_each_block(const chunking& layout, std::size_t c, std::size_t block_points,
                    Block&& block) {
  const std::uint64_t end = layout.end(c);
  for (std::uint64_t first = layout.begin(c); first < end; first += block_points) {
    block(first, static_cast<std::size_t>(std::min<std::uint64_t>(block_points, end - first)));
  }
}

// Calls batch(offset, count) for the batches of a block of `count` points: offset = k·batch_points
// within the block, count = batch_points but for the last, which may be shorter.
template <class Batch>
void for_each_batch_of(std::size_t count, Batch&& batch) {
  for (std::size_t offset = 0; offset < count; offset += batch_points) {
    batch(offset, std::min(batch_points, count - offset));
  }
}

}  // namespace quadmc
