// The t-values and the normalized minimum distance of net_quality.hpp.
#include "quadmc/sampling/net_quality.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/discrepancy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace quadmc {

namespace {

// The points' coordinates on `axes` as 53-digit binary fractions, point by point.
std::vector<std::uint64_t> digits_of(std::span<const double> points, std::size_t s,
                                     std::span<const std::size_t> axes) {
  const std::size_t n = points.size() / s;
  std::vector<std::uint64_t> out(n * axes.size());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double x = points[i * s + axes[a]];
      require(x >= 0.0 && x < 1.0, "point coordinate", x, "a coordinate in [0, 1)");
      out[i * axes.size() + a] = static_cast<std::uint64_t>(std::ldexp(x, 53));
    }
  }
  return out;
}

using shape = std::array<unsigned, max_net_dimension>;

// The composition of `total` into k parts after d, in lexicographic order: the last part j ≤ k − 2
// whose prefix sum Σ d[0 … j] is below `total` goes up by one, the parts after it restart at 0
// and d[k − 1] takes the rest. False after the last, (total, 0, …, 0).
bool next_shape(shape& d, std::size_t k, unsigned total) {
  unsigned prefix = total - d[k - 1];  // Σ d[0 … k − 2]
  for (std::size_t j = k - 1; j-- > 0;) {
    if (prefix < total) {  // prefix = Σ d[0 … j]
      ++d[j];
      for (std::size_t a = j + 1; a + 1 < k; ++a) d[a] = 0;
      d[k - 1] = total - (prefix + 1);
      return true;
    }
    prefix -= d[j];
  }
  return false;
}

// Whether every elementary interval with Σ d_j = m − t holds at most (hence, N = 2^m, exactly)
// 2^t points: over the compositions d of m − t into k parts, from (0, …, 0, m − t), the box of a
// point is its first d_j digits in each coordinate, concatenated.
bool is_net(const std::vector<std::uint64_t>& u, std::size_t k, unsigned m, unsigned t) {
  const unsigned total = m - t;
  const std::uint32_t most = std::uint32_t{1} << t;
  const std::size_t n = u.size() / k;
  std::vector<std::uint32_t> count(std::size_t{1} << total);
  shape d{};
  d[k - 1] = total;
  do {
    std::fill(count.begin(), count.end(), 0u);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t box = 0;
      for (std::size_t a = 0; a < k; ++a) {
        if (d[a] == 0) continue;
        box = (box << d[a]) | (u[i * k + a] >> (53 - d[a]));
      }
      if (++count[box] > most) return false;
    }
  } while (next_shape(d, k, total));
  return true;
}

// C(m + k − 1, k − 1): the shapes of the elementary intervals of volume 2^−m in k coordinates.
double shapes_of(unsigned m, std::size_t k) {
  double c = 1.0;
  for (std::size_t i = 1; i < k; ++i) {
    c = c * static_cast<double>(m + i) / static_cast<double>(i);
  }
  return c;
}

// The densest lattice packing's density in s ≤ 8 dimensions ([Conway & Sloane 1999, Table 1.2]):
// Z, A2, A3, D4, D5, E6, E7, E8.
double packing_density(std::size_t s) {
  constexpr double pi = std::numbers::pi;
  switch (s) {
    case 1:
      return 1.0;
    case 2:
      return pi / std::sqrt(12.0);
    case 3:
      return pi / std::sqrt(18.0);
    case 4:
      return pi * pi / 16.0;
    case 5:
      return pi * pi / (15.0 * std::sqrt(2.0));
    case 6:
      return pi * pi * pi / (48.0 * std::sqrt(3.0));
    case 7:
      return pi * pi * pi / 105.0;
    case 8:
      return pi * pi * pi * pi / 384.0;
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

std::optional<unsigned> net_t_value(std::span<const double> points, std::size_t s,
                                    std::span<const std::size_t> axes) {
  require(s >= 1, "dimension s", s, "s ≥ 1");
  require(points.size() % s == 0, "number of coordinates", points.size(),
          "a multiple of the dimension s");
  const std::size_t n = points.size() / s;
  require(n <= (std::size_t{1} << max_net_log2_points), "number of points N", n,
          "N ≤ 2^20 for a t-value");
  std::vector<std::size_t> all;
  if (axes.empty()) {
    for (std::size_t j = 0; j < s; ++j) all.push_back(j);
    axes = all;
  }
  require(axes.size() <= max_net_dimension, "number of coordinates of a t-value", axes.size(),
          "at most 8");
  for (const std::size_t a : axes) require(a < s, "coordinate of a t-value", a, "an axis below s");
  if (n == 0 || !std::has_single_bit(n)) return std::nullopt;
  const auto m = static_cast<unsigned>(std::countr_zero(n));
  // t = 0 alone counts N points into every shape; the bound keeps that to seconds (s = 4 at
  // N = 2^20 is 1771 shapes, 1.9e9 counts) instead of the hours of s = 8 there (8.9e5 shapes).
  require(shapes_of(m, axes.size()) * static_cast<double>(n) <= max_net_box_counts,
          "number of points N", n,
          fmt::format("C(m + k − 1, k − 1)·N ≤ 2^31 box counts for a t-value in k = {} "
                      "coordinates (fewer points or coordinates)",
                      axes.size()));
  const std::vector<std::uint64_t> u = digits_of(points, s, axes);
  for (unsigned t = 0; t < m; ++t) {
    if (is_net(u, axes.size(), m, t)) return t;
  }
  return m;
}

std::optional<pair_t_values> pairwise_t_values(std::span<const double> points, std::size_t s) {
  require(s >= 1, "dimension s", s, "s ≥ 1");
  const std::size_t n = points.size() / s;
  if (s < 2 || n == 0 || !std::has_single_bit(n)) return std::nullopt;
  pair_t_values out;
  out.best = std::numeric_limits<unsigned>::max();
  for (std::size_t j = 0; j < s; ++j) {
    for (std::size_t k = j + 1; k < s; ++k) {
      const std::array<std::size_t, 2> axes{j, k};
      const unsigned t = *net_t_value(points, s, axes);
      if (t > out.worst) out = {t, out.best, j, k};  // the first pair with the largest t
      out.best = std::min(out.best, t);
    }
  }
  return out;
}

double normalized_min_distance(std::span<const double> points, std::size_t s) {
  require(s >= 1, "dimension s", s, "s ≥ 1");
  require(points.size() % s == 0, "number of coordinates", points.size(),
          "a multiple of the dimension s");
  const std::size_t n = points.size() / s;
  require(n <= max_discrepancy_points, "number of points N", n,
          "N ≤ 2^14 for an O(N²) minimum distance");
  for (const double x : points) {
    require(x >= 0.0 && x <= 1.0, "point coordinate", x, "a coordinate in [0, 1]");
  }
  const double density = packing_density(s);
  if (n < 2 || std::isnan(density)) return std::numeric_limits<double>::quiet_NaN();
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = i + 1; k < n; ++k) {
      double d2 = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double d = points[i * s + j] - points[k * s + j];
        d2 += d * d;
      }
      nearest = std::min(nearest, d2);
    }
  }
  const double sd = static_cast<double>(s);
  const double ball = std::pow(std::numbers::pi, sd / 2.0) / std::tgamma(sd / 2.0 + 1.0);
  const double packed = 2.0 * std::pow(density / (static_cast<double>(n) * ball), 1.0 / sd);
  return std::sqrt(nearest) / packed;
}

}  // namespace quadmc
