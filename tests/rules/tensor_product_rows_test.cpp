// tensor_rows (rules/tensor_product_rows.hpp), the row kernel behind tensor_product_grid's box
// fast path: at every SIMD level this CPU offers, bitwise the points and weights of the template
// walk (generate() followed by cube_to_box::apply), for every dimension the kernels specialise
// (1–8), the run-time loop above them, and batches that start and end anywhere in a row.
#include "quadmc/rules/tensor_product_rows.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product_grid.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "support/floating_point.hpp"
#include "support/simd_level_guard.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

using quadmc::test_support::simd_level_guard;

using quadmc::test_support::bits;

// A box with a different offset and width on every axis, so that a coordinate written to the
// wrong axis or the wrong point cannot go unnoticed.
box uneven_box(std::size_t s) {
  box b;
  for (std::size_t j = 0; j < s; ++j) {
    b.lower.push_back(-0.75 + 0.25 * static_cast<double>(j));
    b.upper.push_back(1.5 + 0.5 * static_cast<double>(j) + 0.001 * static_cast<double>(j * j));
  }
  return b;
}

// The batch [first, first + count) of the grid of `rule` with n panels in s dimensions, through
// the row kernel at every level, against generate() + apply(). The output buffers are filled with
// a marker first and are one point longer than the batch: the kernel must write every entry of
// the batch and nothing past it. A batch that does not fit a small grid is cut to it (first mod
// N, at most N − first points).
template <class R>
void expect_rows_equal_walk(const R& rule, std::uint64_t n, std::size_t s, std::uint64_t first,
                            std::size_t count) {
  const tensor_product_grid grid(rule.nodes(n), s);
  first %= grid.size();
  if (count > grid.size() - first) count = static_cast<std::size_t>(grid.size() - first);
  const cube_to_box map(uneven_box(s));
  std::vector<double> unit(count * s), w_unit(count);
  grid.generate(first, unit, w_unit);
  map.apply(unit);
  const auto on_box = grid.mapped(map);
  const double marker = -12345.5;
  for (const simd_level level : available_simd_levels()) {
    set_simd_level(level);
    std::vector<double> x((count + 1) * s, marker), w(count + 1, marker);
    on_box.generate(first, std::span<double>(x.data(), count * s),
                    std::span<double>(w.data(), count));
    const std::string where = std::string(rule.name()) + ", n " + std::to_string(n) + ", s " +
                              std::to_string(s) + ", first " + std::to_string(first) + ", count " +
                              std::to_string(count) + ", level " + std::string(to_string(level));
    for (std::size_t i = 0; i < count * s; ++i) {
      ASSERT_EQ(bits(x[i]), bits(unit[i])) << where << ", point " << i / s << ", axis " << i % s;
    }
    for (std::size_t i = 0; i < count; ++i) {
      ASSERT_EQ(bits(w[i]), bits(w_unit[i])) << where << ", weight " << i;
    }
    for (std::size_t i = count * s; i < x.size(); ++i) ASSERT_EQ(x[i], marker) << where;
    ASSERT_EQ(w[count], marker) << where;
  }
}

TEST(TensorProductRows, EveryLevelWritesThePointsOfTheWalkInEveryDimension) {
  const simd_level_guard guard;
  // Rows of m = 7, 8, 9 and 11 nodes (shorter, equal to and longer than one or two registers of 4
  // or 8), batches starting mid-row and ending mid-row, partial and whole batches of 256.
  for (std::size_t s = 1; s <= 12; ++s) {
    expect_rows_equal_walk(simpson_rule{}, 6, s, 0, 256);
    expect_rows_equal_walk(trapezoid_rule{}, 7, s, 3, 253);
    expect_rows_equal_walk(trapezoid_rule{}, 8, s, 13, 200);
    expect_rows_equal_walk(midpoint_rule{}, 11, s, 5, 37);
    expect_rows_equal_walk(gauss_legendre_rule(3), 3, s, 1, 1);
  }
}

TEST(TensorProductRows, LongRowsShortRowsAndTheLastPoint) {
  const simd_level_guard guard;
  // m = 2001 (a batch inside one row, and across a carry), m = 2 (a row per 2 points), the
  // largest tabulated axis (m = 2^14), and the grid's very last point.
  expect_rows_equal_walk(simpson_rule{}, 2000, 2, 1'999'900, 256);
  expect_rows_equal_walk(simpson_rule{}, 2000, 2, 2001 * 2001 - 256, 256);
  expect_rows_equal_walk(trapezoid_rule{}, 1, 5, 7, 25);
  expect_rows_equal_walk(midpoint_rule{}, 1 << 14, 1, (1 << 14) - 300, 300);
  expect_rows_equal_walk(midpoint_rule{}, 1 << 14, 3, 12345678, 256);
  expect_rows_equal_walk(trapezoid_rule{}, 1, 63, (std::uint64_t{1} << 63) - 100, 99);
}

}  // namespace
