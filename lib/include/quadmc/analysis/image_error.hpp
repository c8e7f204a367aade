// How the error of an image is spread over spatial frequencies, the measures by which renderers
// judge an image sampler beyond its RMSE ([Ahmed & Wonka 2020]; docs/theory.md#error-spectrum):
// the RMSE left after a Gaussian low-pass, and the error's radially averaged power spectrum.
//
// Use it to tell white-noise error (every pixel on its own: the same power at every frequency)
// from blue-noise error (neighbouring pixels' errors cancel: little power at low frequencies,
// so a low-pass removes most of it, as the eye does at a distance). Not a measure of bias: a
// constant error is all at frequency 0, which the spectrum leaves out and the low-pass keeps.
//
// Definitions, for the error image e (W × H, row-major, pixel (c, r) at r·W + c):
//   lowpass_rmse(σ)  the RMSE of g_σ ∗ e, g_σ the Gaussian of σ pixels sampled at integer
//                    offsets |d| ≤ ⌈4σ⌉ and normalized to sum 1, applied along rows then
//                    columns, e mirrored at the borders (e(−1) = e(0), as
//                    scipy.ndimage.gaussian_filter's default mode); σ = 0 is e itself.
//   spectrum         P(k) = |Σ_p e_p·exp(−2πi(k₁c/W + k₂r/H))|² / (W·H) over the frequencies
//                    f = (k₁/W, k₂/H) in cycles per pixel, divided by the mean square of e, so
//                    that white noise has expected relative power 1 at every f ≠ 0; averaged
//                    over the rings of width 1/64 cycle per pixel, |f| ∈ ((b − 1)/64, b/64],
//                    b = 1 … 32 (up to the Nyquist frequency ½ of the axes; the corners beyond
//                    and f = 0 are left out). For white noise each ring's mean has standard
//                    error 1/√(its frequencies/2) (P(f) = P(−f); each P ~ exponential).
// The transform is FFTW's (Debian's libfftw3), so any W and H cost O(W·H·log(W·H)).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

// Throws invalid_argument unless e.size() = W·H ≥ 1, σ is finite and 0 ≤ σ ≤ 64, and e is finite.
double lowpass_rmse(std::span<const double> e, std::size_t width, std::size_t height, double sigma);

struct spectrum_ring {
  double frequency = 0.0;         // the ring's outer radius b/64, cycles per pixel
  std::uint64_t frequencies = 0;  // of the full plane in the ring (0: empty at this W × H)
  double relative_power = 0.0;    // mean P(f) / mean(e²); NaN for an empty ring or e = 0
};

inline constexpr std::size_t spectrum_rings = 32;

// The 32 rings of e's relative power spectrum. Throws invalid_argument unless e.size() = W·H ≥ 1
// and e is finite.
std::vector<spectrum_ring> error_spectrum(std::span<const double> e, std::size_t width,
                                          std::size_t height);

}  // namespace quadmc
