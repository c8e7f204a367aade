// The row kernel behind tensor_product_grid::on_box (tensor_product_grid.hpp): writes a batch of
// a tabulated tensor grid's points in box coordinates, whole rows of the last axis at a time.
//
// Use it only through tensor_product_grid (it relies on that class's checks). A row is a run of
// points that share their leading coordinates (at most m points): their last coordinates and
// weights come straight from tables built once per call, the leading coordinates are written
// once per point from registers, and the weight is the leading product times the row's weight —
// the same operations in the same order as the template walk of tensor_product_grid.hpp, so the
// same bits (tests/rules/tensor_product_rows_test.cpp checks every SIMD level against it). The
// odometer that carries from one row to the next stays scalar; the rows are vector code chosen at
// run time (core/simd_level.hpp; docs/design.md#hot-path-contract): AVX2 at the avx2 and avx512
// levels, the portable loop below them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

// A tabulated grid's tables for one call, in box coordinates: s ≤ tensor_row_max_axes axes of m
// nodes each (m ≥ 1), axis_x[j·m + k] = x_j of node k, weight[k] = w_k. Borrowed, not owned.
struct tensor_row_tables {
  std::size_t s = 0;
  std::uint64_t m = 0;
  const double* axis_x = nullptr;
  const double* weight = nullptr;
};

// With m ≥ 2 nodes per axis, m^s < 2^64 forces s ≤ 63; grids with more axes have m = 1 and are
// written by tensor_product_grid's own walk.
inline constexpr std::size_t tensor_row_max_axes = 64;

// Points [first, first + count) of the grid, row-major: x[i·s + j], weights[i]. The caller has
// checked the batch (require_weighted_batch): first + count ≤ m^s, x holds count·s doubles.
void tensor_rows(const tensor_row_tables& tables, std::uint64_t first, std::size_t count, double* x,
                 double* weights) noexcept;

}  // namespace quadmc::detail
