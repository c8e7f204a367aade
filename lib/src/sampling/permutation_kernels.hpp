// The vector kernels behind detail::permutation_blocks (sampling/random_permutation.hpp) and
// detail::latin_hypercube_place (sampling/latin_hypercube_points.hpp), one file per instruction
// set, each compiled with that ISA's flag (lib/CMakeLists.txt) and called only after a run-time
// CPU check (core/simd_level.hpp).
#pragma once

#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

void permutation_blocks_scalar(const permutation_schedule& p, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept;
// Element i of the permutation of lane `lane`'s axis (latin_hypercube_lanes): the bijection of
// permutation_schedule with that axis's keys, walked into [0, n).
inline std::uint64_t lane_permutation(const latin_hypercube_lanes& lanes, std::size_t lane,
                                      std::uint64_t i) noexcept {
  std::uint64_t x = i;
  do {
    for (int r = 0; r < permutation_schedule::rounds; ++r) {
      x ^= lanes.keys[(2 * r) * lanes.period + lane];
      x = (x * lanes.keys[(2 * r + 1) * lanes.period + lane]) & lanes.mask;
      x ^= x >> lanes.shift;
    }
  } while (x >= lanes.n);
  return x;
}

// Points [first, first + count) one coordinate at a time: the vector kernels' last points (fewer
// than one block). The conversion and placement of latin_hypercube_points' per-axis loop.
inline void latin_hypercube_place_scalar(const latin_hypercube_lanes& lanes, std::uint64_t first,
                                         std::size_t count, double* x) noexcept {
  for (std::size_t p = 0; p < count; ++p) {
    for (std::size_t j = 0; j < lanes.s; ++j) {
      const auto row =
          static_cast<double>(static_cast<std::int64_t>(lane_permutation(lanes, j, first + p)));
      double& u = x[p * lanes.s + j];
      u = std::min((row + u) * lanes.inv_n, largest_below_one);
    }
  }
}

#if defined(__x86_64__)
// AVX2: n ≤ 2^31 only (8 lanes of 32 bits; the tables' keys32 and point32).
void latin_hypercube_place_avx2(const latin_hypercube_lanes& lanes, std::uint64_t first,
                                std::size_t count, double* x) noexcept;
// AVX-512DQ: any n.
void latin_hypercube_place_avx512(const latin_hypercube_lanes& lanes, std::uint64_t first,
                                  std::size_t count, double* x) noexcept;
void permutation_blocks_avx2(const permutation_schedule& p, std::uint64_t first, std::size_t count,
                             std::uint64_t* out) noexcept;
void permutation_blocks_avx512(const permutation_schedule& p, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept;
#endif

}  // namespace quadmc::detail
