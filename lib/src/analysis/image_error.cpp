// The error image by frequency (image_error.hpp).
#include "quadmc/analysis/image_error.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <mutex>
#include <new>

namespace quadmc {

namespace {

void require_image(std::span<const double> e, std::size_t width, std::size_t height) {
  require(width >= 1 && height >= 1 && width <= (std::size_t{1} << 15) &&
              height <= (std::size_t{1} << 15),
          "image width × height", width * height, "1 … 32768 pixels per side");
  require(e.size() == width * height, "error image size", e.size(), "width × height values");
  const auto bad = std::find_if(e.begin(), e.end(), [](double v) { return !std::isfinite(v); });
  require(bad == e.end(), "error image pixel", bad - e.begin(), "finite errors only");
}

// Index i of a line of n values mirrored at both ends (… b a | a b … y z | z y …), period 2n.
std::size_t reflect(std::ptrdiff_t i, std::size_t n) {
  const auto period = static_cast<std::ptrdiff_t>(2 * n);
  const auto m = static_cast<std::size_t>(((i % period) + period) % period);
  return m < n ? m : 2 * n - 1 - m;
}

// out[j] = Σ_d w[d + r]·in[reflect(j + d)], |d| ≤ r, over `count` values `stride` apart.
void convolve_line(const double* in, double* out, std::size_t count, std::size_t stride,
                   std::span<const double> w) {
  const auto r = static_cast<std::ptrdiff_t>(w.size() / 2);
  for (std::size_t j = 0; j < count; ++j) {
    double sum = 0.0;
    for (std::ptrdiff_t d = -r; d <= r; ++d) {
      sum += w[static_cast<std::size_t>(d + r)] *
             in[reflect(static_cast<std::ptrdiff_t>(j) + d, count) * stride];
    }
    out[j * stride] = sum;
  }
}

double mean_square(std::span<const double> x) {
  neumaier_sum sq;
  for (const double v : x) sq += v * v;
  return sq.value() / static_cast<double>(x.size());
}

struct fftw_free_deleter {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

// FFTW's planner is not thread-safe (its manual, "Thread safety"); executing a plan is.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

double lowpass_rmse(std::span<const double> e, std::size_t width, std::size_t height,
                    double sigma) {
  require_image(e, width, height);
  require(std::isfinite(sigma) && sigma >= 0.0 && sigma <= 64.0, "low-pass sigma (pixels)", sigma,
          "0 ≤ σ ≤ 64");
  if (sigma == 0.0) return std::sqrt(mean_square(e));
  const auto radius = static_cast<std::size_t>(std::ceil(4.0 * sigma));
  std::vector<double> w(2 * radius + 1);
  double total = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double d = static_cast<double>(i) - static_cast<double>(radius);
    w[i] = std::exp(-d * d / (2.0 * sigma * sigma));
    total += w[i];
  }
  for (double& x : w) x /= total;
  std::vector<double> rows(e.size());
  for (std::size_t r = 0; r < height; ++r) {
    convolve_line(e.data() + r * width, rows.data() + r * width, width, 1, w);
  }
  std::vector<double> filtered(e.size());
  for (std::size_t c = 0; c < width; ++c) {
    convolve_line(rows.data() + c, filtered.data() + c, height, width, w);
  }
  return std::sqrt(mean_square(filtered));
}

std::vector<spectrum_ring> error_spectrum(std::span<const double> e, std::size_t width,
                                          std::size_t height) {
  require_image(e, width, height);
  const std::size_t half = width / 2 + 1;  // r2c keeps k₁ = 0 … ⌊W/2⌋
  const std::unique_ptr<double, fftw_free_deleter> in(fftw_alloc_real(e.size()));
  const std::unique_ptr<fftw_complex, fftw_free_deleter> out(fftw_alloc_complex(height * half));
  if (!in || !out) throw std::bad_alloc();
  fftw_plan plan = nullptr;
  {
    const std::lock_guard lock(planner_mutex());
    // FFTW_ESTIMATE: no trial transforms, so the plan (and the bits) do not depend on timing.
    plan = fftw_plan_dft_r2c_2d(static_cast<int>(height), static_cast<int>(width), in.get(),
                                out.get(), FFTW_ESTIMATE);
  }
  require(plan != nullptr, "image width × height", width * height, "a size FFTW can plan");
  std::copy(e.begin(), e.end(), in.get());
  fftw_execute(plan);
  {
    const std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }

  const auto pixels = static_cast<double>(e.size());
  const double mean_sq = mean_square(e);

  std::vector<neumaier_sum> power(spectrum_rings);
  std::vector<std::uint64_t> count(spectrum_rings, 0);
  for (std::size_t k2 = 0; k2 < height; ++k2) {
    const double f2 = (2 * k2 <= height ? static_cast<double>(k2)
                                        : static_cast<double>(k2) - static_cast<double>(height)) /
                      static_cast<double>(height);
    for (std::size_t k1 = 0; k1 < half; ++k1) {
      if (k1 == 0 && k2 == 0) continue;  // the mean error: bias, not noise
      const double f1 = static_cast<double>(k1) / static_cast<double>(width);
      const double radius = std::sqrt(f1 * f1 + f2 * f2);
      if (radius > 0.5) continue;
      // Ring b holds ((b − 1)/64, b/64]: the ceiling of 64·|f|, 1-based.
      const auto ring = static_cast<std::size_t>(std::ceil(radius * 64.0)) - 1;
      const std::complex<double> z(out.get()[k2 * half + k1][0], out.get()[k2 * half + k1][1]);
      // Columns 0 < k₁ < W/2 stand for k₁ and its mirror −k₁ (the transform of a real image is
      // conjugate-symmetric): they count twice in the full plane.
      const std::uint64_t copies = (k1 == 0 || 2 * k1 == width) ? 1 : 2;
      power[ring] += static_cast<double>(copies) * std::norm(z) / pixels;
      count[ring] += copies;
    }
  }
  std::vector<spectrum_ring> rings(spectrum_rings);
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t b = 0; b < spectrum_rings; ++b) {
    rings[b].frequency = static_cast<double>(b + 1) / 64.0;
    rings[b].frequencies = count[b];
    rings[b].relative_power = count[b] == 0 || mean_sq == 0.0
                                  ? nan
                                  : power[b].value() / static_cast<double>(count[b]) / mean_sq;
  }
  return rings;
}

}  // namespace quadmc
