// The smoothness classes of an integrand, which decide the convergence rate theory predicts
// (docs/theory.md#rate-table).
//
// Use it to say how regular a function is (functions/integrand.hpp's integrand_info) and to look
// a rate up (analysis/theoretical_rate.hpp). It lives in core because both the integrands and the
// analysis speak of it, and the analysis layer does not depend on the integrands.
#pragma once

#include <optional>
#include <string_view>

namespace quadmc {

// How regular f is on its domain: decides which convergence rate theory predicts.
enum class smoothness {
  analytic,       // e.g. Genz oscillatory, Gaussian: every rule reaches its full order
  smooth,         // C^k for the k in integrand_info::continuous_derivatives (finite)
  c0,             // continuous with a kink (|x − c|, Genz continuous, Sobol' g)
  discontinuous,  // jumps (step, indicators, Genz discontinuous, occluded irradiance)
  singular,       // unbounded derivative or value at the boundary (√x, 1/√x, log x)
};

constexpr const char* to_string(smoothness s) noexcept {
  switch (s) {
    case smoothness::analytic:
      return "analytic";
    case smoothness::smooth:
      return "smooth";
    case smoothness::c0:
      return "C0";
    case smoothness::discontinuous:
      return "discontinuous";
    case smoothness::singular:
      return "singular";
  }
  return "?";
}

// Inverse of to_string; nullopt for any other text.
constexpr std::optional<smoothness> parse_smoothness(std::string_view text) noexcept {
  for (smoothness s : {smoothness::analytic, smoothness::smooth, smoothness::c0,
                       smoothness::discontinuous, smoothness::singular}) {
    if (text == to_string(s)) return s;
  }
  return std::nullopt;
}

}  // namespace quadmc
