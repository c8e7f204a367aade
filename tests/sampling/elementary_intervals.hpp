// Test support: the elementary intervals of base 2 in one or two coordinates of a point set, for
// the sets built from (0, m, 2)-nets (pmj02, padded Sobol'), whose pairs of coordinates are
// checked one pair at a time.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc::test_support {

// Whether coordinates a and b of points [first, first + 2^m) of the row-major x (s per point)
// form a (0, m, 2)-net: every box [i 2^−d, (i + 1) 2^−d) × [j 2^−(m−d), (j + 1) 2^−(m−d)),
// d = 0 … m, holds exactly one point.
inline bool is_pair_net(std::span<const double> x, std::size_t s, std::size_t a, std::size_t b,
                        std::uint64_t first, unsigned m) {
  const std::uint64_t n = std::uint64_t{1} << m;
  for (unsigned d = 0; d <= m; ++d) {
    std::vector<std::uint8_t> count(n, 0);
    for (std::uint64_t i = first; i < first + n; ++i) {
      const auto u = static_cast<std::uint64_t>(std::ldexp(x[i * s + a], static_cast<int>(d)));
      const auto v = static_cast<std::uint64_t>(std::ldexp(x[i * s + b], static_cast<int>(m - d)));
      if (++count[(u << (m - d)) | v] > 1) return false;
    }
  }
  return true;
}

// Whether coordinate a of points [first, first + 2^m) puts one point in each interval of 2^−m.
inline bool is_interval_net(std::span<const double> x, std::size_t s, std::size_t a,
                            std::uint64_t first, unsigned m) {
  const std::uint64_t n = std::uint64_t{1} << m;
  std::vector<std::uint8_t> count(n, 0);
  for (std::uint64_t i = first; i < first + n; ++i) {
    const auto u = static_cast<std::uint64_t>(std::ldexp(x[i * s + a], static_cast<int>(m)));
    if (++count[u] > 1) return false;
  }
  return true;
}

}  // namespace quadmc::test_support
