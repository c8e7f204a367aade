// The vector placement of jittered points, one per stratum (sampling/jittered_points.hpp): one
// template over the lanes of an instruction set, instantiated per s in jittered_rows.cpp (scalar,
// SSE2) and jittered_rows_{avx2,avx512}.cpp, each compiled with that ISA's flag
// (lib/CMakeLists.txt) and called only after a run-time CPU check (core/simd_level.hpp).
//
// A row of the last axis is the run of points that share their leading cells; inside it, point r
// has the offsets (cell₀, …, cell_{s−2}, c + r). The s·r coordinates of a row are therefore a
// periodic pattern plus a step on the last axis: with W lanes, B = W/gcd(s, W) points fill
// Q = s/gcd(s, W) registers exactly, so those Q registers of offsets are built once per row and
// advanced by B on their last-axis lanes per block. Each coordinate is min((offset + u)·(1/k),
// largest_below_one), the scalar formula's operations on the same operands (the offsets are
// integers < 2^53, exact in double), so every level gives the scalar bits.
#pragma once

#include "quadmc/sampling/jittered_points.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace quadmc::detail {

void jittered_rows_scalar(std::size_t s, double k, double inv_k, const double* cell, double* x,
                          std::size_t count) noexcept;
#if defined(__x86_64__)
void jittered_rows_sse2(std::size_t s, double k, double inv_k, const double* cell, double* x,
                        std::size_t count) noexcept;
void jittered_rows_avx2(std::size_t s, double k, double inv_k, const double* cell, double* x,
                        std::size_t count) noexcept;
void jittered_rows_avx512(std::size_t s, double k, double inv_k, const double* cell, double* x,
                          std::size_t count) noexcept;
#endif

// One coordinate, as every level computes it: std::min's (b < a ? b : a), which is also minpd's
// a < b ? a : b on these operands (no NaN; equal operands give the same value).
inline double jittered_coordinate(double offset, double u, double inv_k) noexcept {
  return std::min((offset + u) * inv_k, largest_below_one);
}

// L: the lanes (reg, lanes, load, store, broadcast, add, mul, min). S: the dimension, 1…8.
template <class L, std::size_t S>
void jittered_rows_kernel(double k, double inv_k, const double* first_cell, double* x,
                          std::size_t count) noexcept {
  using reg = typename L::reg;
  constexpr std::size_t lanes = L::lanes;
  constexpr std::size_t g = std::gcd(S, lanes);
  constexpr std::size_t block_points = lanes / g;  // B
  constexpr std::size_t registers = S / g;         // Q
  double cell[S];
  for (std::size_t j = 0; j < S; ++j) cell[j] = first_cell[j];
  // The per-block step: B on the last-axis lanes, 0 on the others.
  alignas(64) double pattern[block_points * S];
  for (std::size_t t = 0; t < block_points; ++t) {
    for (std::size_t j = 0; j < S; ++j) {
      pattern[t * S + j] = j + 1 == S ? static_cast<double>(block_points) : 0.0;
    }
  }
  reg step[registers];
  for (std::size_t q = 0; q < registers; ++q) step[q] = L::load(pattern + q * lanes);
  constexpr std::size_t chains = registers >= 4 ? 1 : 4 / registers;
  reg chain_step[registers];  // chains·B on the last-axis lanes, exact
  for (std::size_t q = 0; q < registers; ++q) {
    chain_step[q] = L::mul(step[q], L::broadcast(static_cast<double>(chains)));
  }
  // From one whole row to the next without a carry past axis S − 2: +1 on that axis's lanes.
  for (std::size_t t = 0; t < block_points; ++t) {
    for (std::size_t j = 0; j < S; ++j) pattern[t * S + j] = j + 2 == S ? 1.0 : 0.0;
  }
  reg next_row[registers];
  for (std::size_t q = 0; q < registers; ++q) next_row[q] = L::load(pattern + q * lanes);
  const reg scale = L::broadcast(inv_k);
  const reg below_one = L::broadcast(largest_below_one);
  // The offsets of the row's first block. Built through memory (scalar stores, then vector loads,
  // which stall on store-to-load forwarding) only for a batch's first row and after a carry past
  // axis S − 2; otherwise they are the previous row's plus next_row, exact (integers < 2^53), so
  // the same values. Rows are short where s is large (k = 8 points at s = 8, 2^24 points): there
  // the rebuild per row was about 40 % of the placement's time (perf, 14 % → 9 % of the run).
  reg start[registers];
  for (std::size_t q = 0; q < registers; ++q) start[q] = L::broadcast(0.0);  // set before use
  bool start_ready = false;
  std::size_t p = 0;
  while (p < count) {
    const double c = cell[S - 1];
    // Points left in this row (k − c ≥ 1, exact) or in the batch.
    const std::size_t run = std::min(count - p, static_cast<std::size_t>(k - c));
    if (!start_ready) {
      for (std::size_t t = 0; t < block_points; ++t) {
        for (std::size_t j = 0; j + 1 < S; ++j) pattern[t * S + j] = cell[j];
        pattern[t * S + S - 1] = c + static_cast<double>(t);
      }
#pragma GCC unroll 8
      for (std::size_t q = 0; q < registers; ++q) start[q] = L::load(pattern + q * lanes);
    }
    // `chains` blocks per step, each with its own offsets advanced by chains·B: with one or two
    // registers per block, a single chain of offset additions was bound by the addition's
    // latency (≈ 1 cycle per point at s = 1, 5 % of a run; perf). The offsets are the same exact
    // integers however they are reached, so the bits do not change. The loops over the chains
    // and registers are unrolled by force: at -O2 GCC kept offset[][] on the stack, a
    // store-to-load round trip per block (perf annotate, s = 8).
    reg offset[chains][registers];
#pragma GCC unroll 8
    for (std::size_t q = 0; q < registers; ++q) {
      offset[0][q] = start[q];
      for (std::size_t h = 1; h < chains; ++h) offset[h][q] = L::add(offset[h - 1][q], step[q]);
    }
    double* row = x + p * S;
    std::size_t r = 0;
    for (; r + chains * block_points <= run; r += chains * block_points) {
#pragma GCC unroll 8
      for (std::size_t h = 0; h < chains; ++h) {
        double* block = row + (r + h * block_points) * S;
#pragma GCC unroll 8
        for (std::size_t q = 0; q < registers; ++q) {
          const reg u = L::load(block + q * lanes);
          L::store(block + q * lanes, L::min(L::mul(L::add(offset[h][q], u), scale), below_one));
          offset[h][q] = L::add(offset[h][q], chain_step[q]);
        }
      }
    }
    for (; r + block_points <= run; r += block_points) {  // offset[0] is at block r
      double* block = row + r * S;
#pragma GCC unroll 8
      for (std::size_t q = 0; q < registers; ++q) {
        const reg u = L::load(block + q * lanes);
        L::store(block + q * lanes, L::min(L::mul(L::add(offset[0][q], u), scale), below_one));
        offset[0][q] = L::add(offset[0][q], step[q]);
      }
    }
    for (; r < run; ++r) {  // the row's last points, fewer than B
      double* point = row + r * S;
      for (std::size_t j = 0; j + 1 < S; ++j) {
        point[j] = jittered_coordinate(cell[j], point[j], inv_k);
      }
      point[S - 1] = jittered_coordinate(c + static_cast<double>(r), point[S - 1], inv_k);
    }
    p += run;
    cell[S - 1] = c + static_cast<double>(run);
    start_ready = false;
    if (cell[S - 1] == k) {  // the row ends: carry into the leading axes (an odometer)
      cell[S - 1] = 0.0;
      for (std::size_t j = S - 1; j-- > 0;) {
        cell[j] += 1.0;
        if (cell[j] < k) break;
        cell[j] = 0.0;
      }
      // A whole row (it began at c = 0) and axis S − 2 did not wrap (s = 1 has no such axis: its
      // rows all begin alike, and next_row is 0).
      if (c == 0.0 && (S == 1 || cell[S < 2 ? 0 : S - 2] != 0.0)) {
#pragma GCC unroll 8
        for (std::size_t q = 0; q < registers; ++q) start[q] = L::add(start[q], next_row[q]);
        start_ready = true;
      }
    }
  }
}

// The kernel for the s of the call (1 ≤ s ≤ 8).
template <class L>
void jittered_rows_for(std::size_t s, double k, double inv_k, const double* cell, double* x,
                       std::size_t count) noexcept {
  switch (s) {
    case 1:
      return jittered_rows_kernel<L, 1>(k, inv_k, cell, x, count);
    case 2:
      return jittered_rows_kernel<L, 2>(k, inv_k, cell, x, count);
    case 3:
      return jittered_rows_kernel<L, 3>(k, inv_k, cell, x, count);
    case 4:
      return jittered_rows_kernel<L, 4>(k, inv_k, cell, x, count);
    case 5:
      return jittered_rows_kernel<L, 5>(k, inv_k, cell, x, count);
    case 6:
      return jittered_rows_kernel<L, 6>(k, inv_k, cell, x, count);
    case 7:
      return jittered_rows_kernel<L, 7>(k, inv_k, cell, x, count);
    default:
      return jittered_rows_kernel<L, 8>(k, inv_k, cell, x, count);
  }
}

}  // namespace quadmc::detail
