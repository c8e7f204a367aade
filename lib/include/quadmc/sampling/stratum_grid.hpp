// The grid of k^s equal cubic strata of [0,1)^s that jittered and unjittered points fill.
//
// Use it to build, validate or describe a stratification (the scene planner can ask
// is_valid_size() and skip a cell with the reason). Strata are numbered row-major, the last
// axis fastest: stratum c has cell coordinate (c / k^(s−1−j)) mod k along axis j.
//
// Policy when N is not k^s (tested in stratum_grid_test.cpp): REJECT,
// with a message naming the nearest valid sizes below and above. Silently using the largest
// k^s ≤ N points would plot a convergence curve against an N that was not spent, and padding
// with independent points would mix two convergence rates in one column.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace quadmc {

class stratum_grid {
 public:
  // Largest number of strata (and of points) a grid may hold: 2^53, so that every stratum index
  // and cell coordinate is exact in double precision, and N·s stays inside a random stream.
  static constexpr std::uint64_t max_strata = std::uint64_t{1} << 53;

  // k^s, or nothing when it exceeds `limit` (core/integer_powers.hpp: exact, never rounded).
  static constexpr std::optional<std::uint64_t> checked_power(std::uint64_t k, std::size_t s,
                                                              std::uint64_t limit = max_strata) {
    return quadmc::checked_power(k, s, limit);
  }

  // Largest k ≥ 1 with k^s ≤ n (n ≥ 1, s ≥ 1).
  static std::uint64_t root_floor(std::uint64_t n, std::size_t s) {
    const std::uint64_t k = integer_root(n, s);
    return k < 1 ? 1 : k;
  }

  static bool is_valid_size(std::size_t s, std::uint64_t n) {
    if (s == 0 || n == 0) return false;
    const auto p = checked_power(root_floor(n, s), s);
    return p && *p == n;
  }

  // k strata per axis in s dimensions.
  stratum_grid(std::size_t s, std::uint64_t k) : s_(s), k_(k) {
    require(s >= 1, "dimension s", s, "s ≥ 1");
    require(k >= 1, "strata per axis k", k, "k ≥ 1");
    const auto strata = checked_power(k, s);
    if (!strata) {
      throw invalid_argument("strata per axis k", quote(k),
                             "k^s ≤ 2^53 strata with s = " + std::to_string(s) +
                                 " (k^s overflows; use fewer strata or Latin hypercube points)");
    }
    strata_ = *strata;
  }

  // The grid with exactly n strata; rejects n that is not a perfect s-th power.
  static stratum_grid for_size(std::size_t s, std::uint64_t n) {
    require(s >= 1, "dimension s", s, "s ≥ 1");
    require(n >= 1, "number of points N", n, "N ≥ 1");
    const std::uint64_t k = root_floor(n, s);
    const auto below = checked_power(k, s);
    if (below && *below == n) return stratum_grid(s, k);
    const auto above = checked_power(k + 1, s);
    throw invalid_argument("number of points N", quote(n),
                           "N = k^s for stratification in s = " + std::to_string(s) +
                               " dimensions; nearest valid: " + std::to_string(below.value_or(1)) +
                               " = " + std::to_string(k) + "^" + std::to_string(s) +
                               (above ? " or " + std::to_string(*above) + " = " +
                                            std::to_string(k + 1) + "^" + std::to_string(s)
                                      : std::string()) +
                               " (or use latin_hypercube_points, which accept any N)");
  }

  std::size_t dimension() const noexcept { return s_; }
  std::uint64_t per_axis() const noexcept { return k_; }
  std::uint64_t strata() const noexcept { return strata_; }
  double stratum_volume() const noexcept { return 1.0 / static_cast<double>(strata_); }

  // Writes the s cell coordinates of stratum c (row-major, last axis fastest) into cell.
  template <class Out>
  void cell(std::uint64_t c, Out&& cell) const noexcept {
    for (std::size_t j = s_; j-- > 0;) {
      cell[j] = c % k_;
      c /= k_;
    }
  }

  // cell ← the cell of the next stratum, c + 1: a mixed-radix increment (an odometer), so a run
  // of consecutive strata costs no division after its first cell() (s divisions per point
  // otherwise). Past the last stratum it wraps to cell 0.
  template <class Out>
  void next_cell(Out&& cell) const noexcept {
    for (std::size_t j = s_; j-- > 0;) {
      if (++cell[j] < k_) return;
      cell[j] = 0;
    }
  }

 private:
  std::size_t s_;
  std::uint64_t k_;
  std::uint64_t strata_ = 1;
};

}  // namespace quadmc
