// The rate building blocks of theoretical_rate.hpp; their rows are in docs/theory.md#rate-table.
#include "quadmc/analysis/theoretical_rate.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace quadmc {
namespace {

constexpr const char* newton_cotes_source = "docs/theory.md#tensor-rules; [Burden & Faires, §4.4]";
constexpr const char* jump_source = "docs/theory.md#jumps";
constexpr const char* kink_source = "docs/theory.md#kinks";
constexpr const char* sqrt_source = "docs/theory.md#endpoint-singularities";

double dimension_of(const integrand_class& f) {
  require(f.s >= 1, "s", f.s, "a dimension >= 1");
  return static_cast<double>(f.s);
}

}  // namespace

theoretical_rate composite_rule_rate(int order, const integrand_class& f) {
  require(order >= 1, "rule order r", order, "r >= 1");
  const double s = dimension_of(f);
  const double alpha = f.singularity_exponent;
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
      return {-order / s, fmt::format("order {} rule, f ∈ C^{} assumed", order, order),
              newton_cotes_source};
    case smoothness::c0:
      // A kink costs O(h²) in its panel; rules of order < 2 keep their own order.
      return {-std::min(order, 2) / s, "piecewise C² with a kink: order capped at 2", kink_source};
    case smoothness::discontinuous:
      return {-1.0 / s, "jump: O(n^-1), not monotone in n", jump_source};
    case smoothness::singular:
      break;
  }
  // singular with a known exponent, f ~ x^α: the panel at the singularity errs by
  // ∫₀ʰ x^α dx = O(h^(1+α)) (docs/theory.md#endpoint-singularities; [Davis & Rabinowitz, §2.12]),
  // the others by O(h^r): the rate is n^−min(r, 1+α); for α = 0 (log x) up to a log n factor.
  if (std::isfinite(alpha)) {
    const double rate = std::min(static_cast<double>(order), 1.0 + alpha);
    return {-rate / s,
            fmt::format("endpoint singularity f ~ x^{}: order min(r, 1 + α) = {}{}", alpha, rate,
                        alpha == 0.0 ? " (log x: up to a log n factor)" : ""),
            "docs/theory.md#endpoint-singularities; [Davis & Rabinowitz, §2.12]"};
  }
  // √x-type endpoint singularity. Rectangles keep O(h) (f monotone, bounded variation).
  if (order == 1) {
    return {-1.0 / s, "√x-type singularity: f of bounded variation keeps O(h)",
            "docs/theory.md#endpoint-singularities (rectangles); [Burden & Faires, §4.4]"};
  }
  return {-1.5 / s, "√x-type endpoint singularity assumed", sqrt_source};
}

theoretical_rate extrapolated_trapezoid_rate(const integrand_class& f) {
  (void)dimension_of(f);
  if (f.regularity == smoothness::analytic) {
    return {std::nullopt, "exponential convergence: no finite algebraic slope",
            "docs/theory.md#exponential-convergence; [Trefethen ATAP, Thm 19.3]"};
  }
  if (f.regularity == smoothness::smooth) {
    return {std::nullopt, "algebraic of the order of f's smoothness, unknown from the class",
            "docs/theory.md#exponential-convergence; [Trefethen ATAP, Thm 19.3]"};
  }
  // Richardson extrapolation assumes the Euler–Maclaurin expansion in h²; a kink, jump or √x
  // breaks it past its first term, leaving the trapezoid rate.
  theoretical_rate rate = composite_rule_rate(2, f);
  rate.note = "extrapolation gains nothing past the trapezoid rate; " + rate.note;
  return rate;
}

std::optional<theoretical_rate> infinite_variance_rate(const integrand_class& f) {
  (void)dimension_of(f);
  const double alpha = f.singularity_exponent;
  if (f.regularity != smoothness::singular || !std::isfinite(alpha) || alpha > -0.5) {
    return std::nullopt;
  }
  // ∫f² = ∫x^(2α) diverges for α ≤ −1/2: no finite variance, so neither σ/√N nor the CLT holds
  // (docs/theory.md#infinite-variance); the error still shrinks, at no tabulated rate.
  return theoretical_rate{std::nullopt,
                          fmt::format("f ~ x^{}: infinite variance, no σ/√N rate", alpha),
                          "docs/theory.md#infinite-variance"};
}

theoretical_rate root_n_rate(const integrand_class& f, std::string note, std::string source) {
  if (auto none = infinite_variance_rate(f)) return *none;
  return {-0.5, std::move(note), std::move(source)};
}

theoretical_rate adaptive_monte_carlo_rate(const integrand_class& f, std::string note,
                                           std::string source) {
  theoretical_rate rate = root_n_rate(f, std::move(note), std::move(source));
  rate.adaptive = rate.slope.has_value();
  return rate;
}

theoretical_rate sparse_grid_rate(const integrand_class& f) {
  (void)dimension_of(f);
  constexpr const char* source = "docs/theory.md#sparse-grid-rates; [Novak & Ritter 1996]";
  switch (f.regularity) {
    case smoothness::analytic:
      return {std::nullopt,
              "analytic f: faster than any power of N (no finite slope); compared at equal N",
              source};
    case smoothness::smooth:
      return {std::nullopt,
              "O(N^-r (log N)^((s-1)(r+1))) for mixed smoothness r, unknown from the class",
              source};
    case smoothness::c0:
      // Bounded mixed first derivatives (the catalogue's kinks lie along coordinate planes):
      // r = 1. A kink costs Clenshaw–Curtis O(n^-2) in 1D, so a steeper measured slope is no
      // contradiction; the (log N)^(2(s-1)) factor flattens it in high s.
      return {-1.0,
              "bounded mixed first derivatives (kinks along coordinate planes): "
              "O(N^-1 (log N)^(2(s-1))), a bound",
              source};
    case smoothness::discontinuous:
      return {std::nullopt, "a jump has no mixed smoothness: no proven rate",
              "docs/theory.md#sparse-grid-rates"};
    case smoothness::singular:
      break;
  }
  return {std::nullopt, "a singular f has no mixed smoothness: no proven rate",
          "docs/theory.md#sparse-grid-rates"};
}

theoretical_rate one_point_per_stratum_rate(const integrand_class& f) {
  const double s = dimension_of(f);
  if (auto none = infinite_variance_rate(f)) return *none;
  if (f.regularity == smoothness::discontinuous) {
    return {-0.5 - 1.0 / (2.0 * s), "indicator of a smooth-boundary region",
            "docs/theory.md#jittered; [Mitchell 1996]; [Pilleboue et al. 2015]"};
  }
  if (f.regularity == smoothness::singular) {
    return {std::nullopt, "not tabulated for a singular f", "docs/theory.md#jittered"};
  }
  return {-0.5 - 1.0 / s, "one point per cell, N = m^s; f Lipschitz (C0 kinks included)",
          "docs/theory.md#jittered; [Mitchell 1996]; [Pilleboue et al. 2015]"};
}

theoretical_rate scrambled_net_rate(const integrand_class& f) {
  const double s = dimension_of(f);
  if (auto none = infinite_variance_rate(f)) return *none;
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
      return {-1.5,
              fmt::format("scrambled (t,m,s)-net, N = 2^m: N^-3/2 up to (log N)^{}", (s - 1) / 2),
              "docs/theory.md#scrambled-nets; [Owen 1997b]", (s - 1) / 2};
    case smoothness::c0:
      // In 1D a scrambled (0, m, 1)-net is one uniform point per interval of 2^−m: jittered.
      if (f.s == 1) {
        return {-1.5, "1D: one point per interval of 2^-m (jittered); f Lipschitz",
                "docs/theory.md#scrambled-nets; docs/theory.md#jittered"};
      }
      return {std::nullopt, "kinks in s >= 2: Owen's N^-3/2 needs smooth mixed derivatives",
              "docs/theory.md#scrambled-nets"};
    case smoothness::discontinuous:
      // Jumps on coordinate planes only: f has bounded Hardy–Krause variation, and every
      // randomization is still a (t, m, s)-net, whose star discrepancy is O((log N)^(s−1)/N), so
      // Koksma–Hlawka bounds each error by V_HK(f)·D* (docs/theory.md#scrambled-nets).
      if (f.separable_jumps && f.s >= 2) {
        return {-1.0,
                fmt::format("jumps on coordinate planes (bounded Hardy-Krause variation): "
                            "Koksma-Hlawka with a net's D*, N^-1 up to (log N)^{}",
                            s - 1),
                "docs/theory.md#scrambled-nets; [Niederreiter 1992]", s - 1};
      }
      return {-0.5 - 1.0 / (4.0 * s - 2.0), "indicator of a smooth-boundary region",
              "docs/theory.md#scrambled-nets; [He & Wang 2015]"};
    case smoothness::singular:
      break;
  }
  return {std::nullopt, "not tabulated for a singular f", "docs/theory.md#scrambled-nets"};
}

theoretical_rate interlaced_net_rate(const integrand_class& f, unsigned order, bool scrambled) {
  const double s = dimension_of(f);
  require(order >= 2, "interlacing order α", order, "α ≥ 2 (α = 1 is the Sobol' net itself)");
  if (auto none = infinite_variance_rate(f)) return *none;
  const double alpha = static_cast<double>(order);
  const char* source = scrambled ? "docs/theory.md#interlaced-nets; [Dick 2011]"
                                 : "docs/theory.md#interlaced-nets; [Dick 2008]";
  // The log factors of both bounds grow with α·s; the fitted slopes of short ladders are shallower.
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
      if (scrambled) {
        return {-(alpha + 0.5),
                fmt::format("Owen-scrambled order-{} net, N = 2^m: RMSE N^-{} up to log factors "
                            "(f with mixed derivatives of order δ ≥ {}; log N power grows with "
                            "α·s = {})",
                            order, alpha + 0.5, order, alpha * s),
                source};
      }
      return {-alpha,
              fmt::format("order-{} net, deterministic or digitally shifted, N = 2^m: N^-{} up to "
                          "log factors (f with mixed derivatives of order δ ≥ {})",
                          order, alpha, order),
              source};
    case smoothness::c0:
      return {std::nullopt,
              "kinks: smoothness δ ≤ 1, below the order the interlacing targets; no rate proven "
              "here for the interlaced net",
              "docs/theory.md#interlaced-nets"};
    case smoothness::discontinuous:
      return {std::nullopt,
              "a jump: no smoothness δ, Dick's bounds do not apply; no rate proven for the "
              "interlaced net",
              "docs/theory.md#interlaced-nets"};
    case smoothness::singular:
      break;
  }
  return {std::nullopt, "not tabulated for a singular f", "docs/theory.md#interlaced-nets"};
}

theoretical_rate low_discrepancy_rate(const integrand_class& f, std::string note,
                                      std::string source) {
  (void)dimension_of(f);
  if (auto none = infinite_variance_rate(f)) return *none;
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
    case smoothness::c0:
      return {-1.0, std::move(note) + "; Koksma-Hlawka, D* = O((log N)^s/N): log factors",
              std::move(source)};
    case smoothness::discontinuous:
      return {std::nullopt, "a jump: Hardy-Krause variation infinite (curved) or no rate tabulated",
              std::move(source)};
    case smoothness::singular:
      break;
  }
  return {std::nullopt, "not tabulated for a singular f", std::move(source)};
}

namespace {

// A weighted periodization (c0 … c3sin): g = f(φ(x))∏φ'(x_j), periodic through order k.
theoretical_rate weighted_lattice_rate(const integrand_class& f, const lattice_periodizing& p) {
  constexpr const char* source =
      "docs/theory.md#lattice-periodizations; [Sidi 1993]; [Laurie 1996]; [Sloan & Joe 1994]; "
      "[Dick, Kuo & Sloan 2013]";
  const int m = p.periodic_order + 1;  // the order of φ''s zeros at 0 and 1
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
      return {-static_cast<double>(m + 1),
              fmt::format("shifted lattice + {} transform (phi' zero of order {} at 0 and 1): "
                          "N^(-{}+e), its constant growing with the order and with s",
                          p.name, m, m + 1),
              source};
    case smoothness::c0:
      return {-1.0,
              fmt::format("{} transform on kinks: mixed first derivatives only, N^(-1+e)", p.name),
              source};
    case smoothness::discontinuous:
      return {std::nullopt, "a jump: no lattice rate tabulated", source};
    case smoothness::singular:
      break;
  }
  // The Jacobian's zeros can tame f ~ x^α (g ~ x^((m+1)α+m)), so f's infinite variance is not
  // g's; but no rate is proven here.
  return {std::nullopt,
          fmt::format("not tabulated for a singular f ({} transform: no rate proven)", p.name),
          source};
}

}  // namespace

theoretical_rate shifted_lattice_rate(const integrand_class& f, const lattice_periodizing& p) {
  (void)dimension_of(f);
  if (p.weighted) return weighted_lattice_rate(f, p);
  if (auto none = infinite_variance_rate(f)) return *none;
  const bool baker = p.periodic_order >= 0;
  const char* source = baker ? "docs/theory.md#lattice-rules; [Hickernell 2002]; "
                               "[Dick, Nuyens & Pillichshammer 2014]"
                             : "docs/theory.md#lattice-rules; [Dick, Kuo & Sloan 2013]";
  switch (f.regularity) {
    case smoothness::analytic:
    case smoothness::smooth:
      if (baker) return {-2.0, "shifted lattice + baker's transform: N^(-2+e)", source};
      return {-1.0, "randomly shifted lattice, f not periodic: N^(-1+e)", source};
    case smoothness::c0:
      return {-1.0, "mixed first derivatives only (kinks): N^(-1+e)", source};
    case smoothness::discontinuous:
      return {std::nullopt, "a jump: no lattice rate tabulated", source};
    case smoothness::singular:
      break;
  }
  return {std::nullopt, "not tabulated for a singular f", source};
}

theoretical_rate broken_net_rate(const integrand_class& f, std::string note) {
  (void)dimension_of(f);
  if (auto none = infinite_variance_rate(f)) return *none;
  if (f.regularity == smoothness::analytic || f.regularity == smoothness::smooth) {
    return {-1.0, std::move(note) + ": no net, N^-1",
            "docs/theory.md#sobol-anti-patterns; [Owen 2022]"};
  }
  return {std::nullopt, std::move(note) + ": no rate tabulated beyond smooth f",
          "docs/theory.md#sobol-anti-patterns"};
}

}  // namespace quadmc
