// Exact integer powers and roots: how many points a grid of k per axis has in s dimensions, and
// the largest k whose grid fits a budget of N points.
//
// Use them wherever a count is k^s (tensor grids, stratified point sets, the planner's N → grid
// mapping). Not for floating-point powers: std::pow(4096, 1/3.) is 15.999…, which would floor to
// the wrong grid, so nothing here rounds.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

namespace quadmc {

// base^exponent, or nullopt when it exceeds `limit` (default 2^64 − 1). Each multiplication is
// checked before it is made (p > limit/base ⇔ p·base > limit), so the test is exact.
constexpr std::optional<std::uint64_t> checked_power(
    std::uint64_t base, std::size_t exponent,
    std::uint64_t limit = std::numeric_limits<std::uint64_t>::max()) noexcept {
  std::uint64_t result = 1;
  for (std::size_t i = 0; i < exponent; ++i) {
    if (base != 0 && result > limit / base) return std::nullopt;
    result *= base;
  }
  if (result > limit) return std::nullopt;
  return result;
}

// The largest q ≥ 0 with q^s ≤ n (s ≥ 1; s = 0 gives 0). pow() gives a guess within a few units
// of the root; exact powers then walk it to the right integer, so its rounding cannot move the
// answer.
inline std::uint64_t integer_root(std::uint64_t n, std::size_t s) noexcept {
  if (s == 0) return 0;
  if (s == 1 || n <= 1) return n;
  auto q =
      static_cast<std::uint64_t>(std::pow(static_cast<double>(n), 1.0 / static_cast<double>(s)));
  auto fits = [&](std::uint64_t c) { return checked_power(c, s, n).has_value(); };
  while (q > 0 && !fits(q)) --q;
  while (fits(q + 1)) ++q;
  return q;
}

}  // namespace quadmc
