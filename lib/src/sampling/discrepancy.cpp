// The L2 discrepancies of discrepancy.hpp: one pass over the pairs i < k, the three products of
// each pair built dimension by dimension over a row of k (contiguous, so the compiler vectorises
// it), row sums in four lanes and rows added with Neumaier summation: D² is a small difference of
// O(1) sums (D² ~ 1/N² against terms of order 1), so the sums must carry their digits.
#include "quadmc/sampling/discrepancy.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <algorithm>
#include <cmath>

namespace quadmc {

namespace {

double four_lane_sum(const double* y, std::size_t n) noexcept {
  double lane[4] = {0.0, 0.0, 0.0, 0.0};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    for (std::size_t l = 0; l < 4; ++l) lane[l] += y[i + l];
  }
  for (std::size_t l = 0; i < n; ++i, ++l) lane[l] += y[i];
  return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

double root(double square) {
  return square > 0.0 ? std::sqrt(square) : 0.0;
}

}  // namespace

l2_discrepancies discrepancies(std::span<const double> points, std::size_t s) {
  require(s >= 1, "dimension s", s, "s ≥ 1");
  require(points.size() % s == 0, "number of coordinates", points.size(),
          "a multiple of the dimension s");
  const std::size_t n = points.size() / s;
  require(n >= 1, "number of points N", n, "N ≥ 1");
  require(n <= max_discrepancy_points, "number of points N", n,
          "N ≤ 2^14 for an O(N²) discrepancy");
  for (std::size_t k = 0; k < points.size(); ++k) {
    require(points[k] >= 0.0 && points[k] <= 1.0, "point coordinate", points[k],
            "a coordinate in [0, 1]");
  }
  // Column-major copies: x[j][k] and a[j][k] = |x − ½|.
  std::vector<double> x(n * s), a(n * s);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      x[j * n + i] = points[i * s + j];
      a[j * n + i] = std::abs(points[i * s + j] - 0.5);
    }
  }
  std::vector<double> star(n), centered(n), wrap(n);
  neumaier_sum star_pairs, centered_pairs, wrap_pairs;  // Σ over i < k
  neumaier_sum star_diagonal, centered_diagonal;        // Σ over i = k
  neumaier_sum star_single, centered_single;            // the Σᵢ Πⱼ terms
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t rest = n - i - 1;
    std::fill_n(star.begin(), rest, 1.0);
    std::fill_n(centered.begin(), rest, 1.0);
    std::fill_n(wrap.begin(), rest, 1.0);
    double star_ii = 1.0, centered_ii = 1.0, star_i = 1.0, centered_i = 1.0;
    for (std::size_t j = 0; j < s; ++j) {
      const double xi = x[j * n + i];
      const double ai = a[j * n + i];
      star_ii *= 1.0 - xi;
      centered_ii *= 1.0 + ai;
      star_i *= 1.0 - xi * xi;
      centered_i *= 1.0 + 0.5 * ai - 0.5 * ai * ai;
      const double* xk = x.data() + j * n + i + 1;
      const double* ak = a.data() + j * n + i + 1;
      for (std::size_t k = 0; k < rest; ++k) {
        const double d = std::abs(xi - xk[k]);
        star[k] *= 1.0 - std::max(xi, xk[k]);
        centered[k] *= 1.0 + 0.5 * ai + 0.5 * ak[k] - 0.5 * d;
        wrap[k] *= 1.5 - d * (1.0 - d);
      }
    }
    star_pairs += four_lane_sum(star.data(), rest);
    centered_pairs += four_lane_sum(centered.data(), rest);
    wrap_pairs += four_lane_sum(wrap.data(), rest);
    star_diagonal += star_ii;
    centered_diagonal += centered_ii;
    star_single += star_i;
    centered_single += centered_i;
  }
  const double N = static_cast<double>(n);
  const double sd = static_cast<double>(s);
  const double pairs_scale = 1.0 / (N * N);
  // Σᵢ Σₖ = diagonal + 2 Σ_(i<k).
  const double star_square = std::pow(3.0, -sd) -
                             std::pow(2.0, 1.0 - sd) / N * star_single.value() +
                             pairs_scale * (star_diagonal.value() + 2.0 * star_pairs.value());
  const double centered_square =
      std::pow(13.0 / 12.0, sd) - 2.0 / N * centered_single.value() +
      pairs_scale * (centered_diagonal.value() + 2.0 * centered_pairs.value());
  const double wrap_square =
      -std::pow(4.0 / 3.0, sd) + pairs_scale * (N * std::pow(1.5, sd) + 2.0 * wrap_pairs.value());
  return {root(star_square), root(centered_square), root(wrap_square)};
}

double l2_star_discrepancy(std::span<const double> points, std::size_t s) {
  return discrepancies(points, s).l2_star;
}
double centered_discrepancy(std::span<const double> points, std::size_t s) {
  return discrepancies(points, s).centered;
}
double wraparound_discrepancy(std::span<const double> points, std::size_t s) {
  return discrepancies(points, s).wraparound;
}

}  // namespace quadmc
