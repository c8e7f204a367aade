// The radially averaged periodogram of periodogram.hpp. exp(−2πi f₁x) and exp(−2πi f₂y) are
// tabulated once per realization (angles reduced modulo 1 before the multiplication by 2π, so
// they stay accurate at high f); each frequency is then a complex dot product over the points,
// summed in four lanes so that the loop vectorises without reassociating floating point.
#include "quadmc/sampling/periodogram.hpp"

#include "quadmc/core/errors.hpp"

#include <cmath>
#include <numbers>

namespace quadmc {

namespace {

// exp(−2πi·m·t) for m = 0 … count − 1 and every t, into (re, im)[m·N + j].
void tabulate(std::span<const double> points, std::size_t axis, std::size_t n, std::size_t count,
              std::vector<double>& re, std::vector<double>& im) {
  re.resize(count * n);
  im.resize(count * n);
  for (std::size_t m = 0; m < count; ++m) {
    for (std::size_t j = 0; j < n; ++j) {
      const double t = static_cast<double>(m) * points[2 * j + axis];
      const double angle = 2.0 * std::numbers::pi * (t - std::floor(t));
      re[m * n + j] = std::cos(angle);
      im[m * n + j] = -std::sin(angle);
    }
  }
}

}  // namespace

std::uint64_t half_plane_frequencies(std::size_t radius) {
  const auto r = static_cast<std::int64_t>(radius);
  const std::int64_t low = r * r - r + 1;
  const std::int64_t high = r * r + r;
  std::uint64_t count = 0;
  for (std::int64_t f1 = 0; f1 <= r; ++f1) {
    for (std::int64_t f2 = -r; f2 <= r; ++f2) {
      if (f1 == 0 && f2 <= 0) continue;
      const std::int64_t q = f1 * f1 + f2 * f2;
      if (q >= low && q <= high) ++count;
    }
  }
  return count;
}

radial_periodogram::radial_periodogram(std::size_t max_radius)
    : max_radius_(max_radius), bin_means_(max_radius) {
  require(max_radius >= 1 && max_radius <= 4096, "periodogram max radius", max_radius,
          "1 ≤ max radius ≤ 4096");
}

void radial_periodogram::add(std::span<const double> points) {
  require(points.size() % 2 == 0 && !points.empty(), "number of coordinates", points.size(),
          "an even number > 0 (2D points, row-major)");
  for (const double c : points) {
    require(std::isfinite(c), "point coordinate", c, "a finite coordinate");
  }
  const std::size_t n = points.size() / 2;
  const std::size_t count = max_radius_ + 1;
  // x: f₁ = 0 … R; y: f₂ = 0 … R, negative f₂ by conjugation.
  std::vector<double> xr, xi, yr, yi;
  tabulate(points, 0, n, count, xr, xi);
  tabulate(points, 1, n, count, yr, yi);
  const auto r = static_cast<std::int64_t>(max_radius_);
  const std::int64_t highest = r * r + r;
  std::vector<double> power_sum(max_radius_, 0.0);
  std::vector<std::uint64_t> in_bin(max_radius_, 0);
  for (std::int64_t f1 = 0; f1 <= r; ++f1) {
    const double* ar = &xr[static_cast<std::size_t>(f1) * n];
    const double* ai = &xi[static_cast<std::size_t>(f1) * n];
    for (std::int64_t f2 = -r; f2 <= r; ++f2) {
      if (f1 == 0 && f2 <= 0) continue;
      const std::int64_t q = f1 * f1 + f2 * f2;
      if (q > highest) continue;
      // round(|f|) = r  ⇔  r² − r + 1 ≤ q ≤ r² + r; the bin is the r with (r − ½)² < q.
      auto bin = static_cast<std::size_t>(std::floor(std::sqrt(static_cast<double>(q)) + 0.5));
      while (bin * bin + bin < static_cast<std::size_t>(q)) ++bin;
      while (bin > 1 && (bin - 1) * (bin - 1) + (bin - 1) >= static_cast<std::size_t>(q)) --bin;
      const std::size_t m = static_cast<std::size_t>(f2 < 0 ? -f2 : f2);
      const double* br = &yr[m * n];
      const double* bi = &yi[m * n];
      const double sign = f2 < 0 ? -1.0 : 1.0;  // exp(+2πi|f₂|y) = conj(exp(−2πi|f₂|y))
      double re[4] = {0.0, 0.0, 0.0, 0.0};
      double im[4] = {0.0, 0.0, 0.0, 0.0};
      std::size_t j = 0;
      for (; j + 4 <= n; j += 4) {
        for (std::size_t l = 0; l < 4; ++l) {
          const double cr = br[j + l];
          const double ci = sign * bi[j + l];
          re[l] += ar[j + l] * cr - ai[j + l] * ci;
          im[l] += ar[j + l] * ci + ai[j + l] * cr;
        }
      }
      for (std::size_t l = 0; j < n; ++j, ++l) {
        const double cr = br[j];
        const double ci = sign * bi[j];
        re[l] += ar[j] * cr - ai[j] * ci;
        im[l] += ar[j] * ci + ai[j] * cr;
      }
      const double sr = (re[0] + re[1]) + (re[2] + re[3]);
      const double si = (im[0] + im[1]) + (im[2] + im[3]);
      power_sum[bin - 1] += (sr * sr + si * si) / static_cast<double>(n);
      ++in_bin[bin - 1];
    }
  }
  for (std::size_t b = 0; b < max_radius_; ++b) {
    bin_means_[b].add(power_sum[b] / static_cast<double>(in_bin[b]));
  }
  ++realizations_;
}

std::vector<radial_power_bin> radial_periodogram::bins() const {
  std::vector<radial_power_bin> out(max_radius_);
  for (std::size_t b = 0; b < max_radius_; ++b) {
    out[b].radius = b + 1;
    out[b].frequencies = half_plane_frequencies(b + 1);
    out[b].mean_power = bin_means_[b].mean();
    out[b].standard_error = bin_means_[b].std_error();
  }
  return out;
}

}  // namespace quadmc
