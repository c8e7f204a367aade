// The theoretical convergence rates: the slope of RMSE (or |error| for a deterministic rule)
// against N = total evaluations, for a kind of method on a smoothness class in s dimensions.
//
// Use it to put a "theory" column beside every fitted slope and to decide the verdict
// (slope_verdict.hpp). Each method chooses its rate from these building blocks in its
// descriptor (methods/ layer): which rate a method has is the method's business, what the rate
// of a kind of method is on a kind of integrand is this file's. Every rate carries its source:
// the row of docs/theory.md#rate-table and its references ([Key] entries of docs/references.md).
// Not a bound with a constant: only the exponent; pre-asymptotic ladders can show other slopes
// (docs/theory.md#pre-asymptotic-ladders: fit slopes, never compare with an asymptotic formula
// such as (log N)^s/N).
//
// Deterministic rules are tensor products with n nodes per axis, N = nˢ, so a 1D rate n^−r
// becomes N^(−r/s). Assumptions the class cannot carry are stated in the note: "smooth" means
// smooth enough for the rule's full order; "singular" means an integrable endpoint singularity
// f ~ x^α (the √x kind, α = 1/2, when α is not given: docs/theory.md#endpoint-singularities),
// and Monte Carlo needs finite variance (1/√x has none: docs/theory.md#infinite-variance).
#pragma once

#include "quadmc/core/smoothness.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace quadmc {

struct theoretical_rate {
  std::optional<double> slope;  // empty: no finite algebraic slope (exponential) or no entry
  std::string note;             // the assumption or why there is no slope
  std::string source;           // where the rate comes from
  // q of a proven bound N^slope·(log N)^q (a scrambled net's (s − 1)/2); 0: none stated. Over a
  // finite ladder such a bound falls with the local slope slope + q·Δln ln N/Δln N, which the
  // verdict takes as a computed reason (docs/theory.md#pre-asymptotic-ladders).
  double log_power = 0.0;
  // An adaptive Monte Carlo method (VEGAS, MISER): N^(−1/2) holds once the variance of what it
  // adapts has settled, and until then the error estimate it reports per cell predicts the slope,
  // which the verdict takes as a computed reason (docs/theory.md#adaptive-monte-carlo-ladders).
  bool adaptive = false;
};

// What a rate depends on besides the method.
struct integrand_class {
  smoothness regularity = smoothness::analytic;
  std::size_t s = 1;
  // α for a singular f ~ x^α at an endpoint (α = 0 for log x); NaN = not given (√x assumed).
  double singularity_exponent = std::numeric_limits<double>::quiet_NaN();
  // A discontinuous f that is a product of piecewise-smooth functions of one coordinate each
  // (integrand_info::separable_factors: jumps only on coordinate planes, as Genz's discontinuous
  // family): of bounded Hardy–Krause variation, which a curved or oblique jump is not.
  bool separable_jumps = false;
};

// A composite rule of algebraic order r (error O(n^−r) on f ∈ C^r), as a tensor product in s
// dimensions: −r/s on smooth f; a kink caps the order at 2, a jump at 1, an endpoint singularity
// f ~ x^α at min(r, 1 + α). Throws invalid_argument for s = 0 or r < 1.
theoretical_rate composite_rule_rate(int order, const integrand_class& f);

// Richardson extrapolation of the trapezoid rule (Romberg): exponential on analytic f, of f's
// own unknown order on smooth f (no slope for either), the trapezoid rate once a kink, jump or
// singularity breaks the Euler–Maclaurin expansion.
theoretical_rate extrapolated_trapezoid_rate(const integrand_class& f);

// Whether f has a finite variance, which every Monte Carlo rate needs: not for f ~ x^α with
// α ≤ −1/2 (∫x^(2α) diverges). The rate without a slope that says so, or nullopt.
std::optional<theoretical_rate> infinite_variance_rate(const integrand_class& f);

// σ/√N: −1/2 for a Monte Carlo method of finite variance, with the method's note and source
// (infinite variance first gives no slope).
theoretical_rate root_n_rate(const integrand_class& f, std::string note, std::string source);

// root_n_rate of an adaptive Monte Carlo method (theoretical_rate::adaptive).
theoretical_rate adaptive_monte_carlo_rate(const integrand_class& f, std::string note,
                                           std::string source);

// A Smolyak sparse grid on nested rules (docs/theory.md#sparse-grid-rates): for bounded mixed
// derivatives of order r the error is O(N^−r·(log N)^((s−1)(r+1))) [Novak & Ritter 1996], so the
// slope is −r up to the logarithm: −1 on a C0 f with bounded mixed first derivatives (the kinks
// of the catalogue lie along coordinate planes); no finite slope on analytic f (faster than any
// power: compared at equal N instead) or smooth f (r unknown from the class); none on a jump or a
// singularity (no mixed smoothness: the jump of Genz's discontinuous family and the disk's).
theoretical_rate sparse_grid_rate(const integrand_class& f);

// One point in each of N = k^s equal strata (jittered sampling and what reduces to it):
// −1/2 − 1/s for Lipschitz f, −1/2 − 1/(2s) for the indicator of a region with a smooth
// boundary, no tabulated slope for a singular f.
theoretical_rate one_point_per_stratum_rate(const integrand_class& f);

// Randomized quasi-Monte Carlo (docs/theory.md#quasi-monte-carlo). N = 2^m points of a (t, m,
// s)-net under nested uniform or random linear scrambling: −3/2 on smooth f, up to (log
// N)^((s−1)/2)
// ([Owen 1997b]); −1/2 − 1/(4s − 2) on the indicator of a region with a smooth boundary
// ([He & Wang 2015]); in 1D (one point per interval of 2^−m) the jittered rates; no tabulated
// rate for kinks in s ≥ 2 or singular f.
theoretical_rate scrambled_net_rate(const integrand_class& f);

// An order-α digital net by digit interlacing (docs/theory.md#interlaced-nets), α ≥ 2, N = 2^m.
// For f with square-integrable mixed partial derivatives of order δ: RMSE −(min(α, δ) + 1/2) when
// the αs-dimensional net is Owen-scrambled before interlacing ([Dick 2011]), −min(α, δ) when it
// is deterministic or digitally shifted ([Dick 2008]), both up to log factors. δ = ∞ for analytic
// f; for smooth f δ ≥ α is assumed (the class does not carry δ, as for the rules' full order). No
// rate for kinks (δ = 1 at most, with no proof for the interlaced net here), jumps or singular f.
// Throws invalid_argument for α < 2.
theoretical_rate interlaced_net_rate(const integrand_class& f, unsigned order, bool scrambled);

// Points whose randomization (if any) leaves their discrepancy as it is — a digital shift, the
// unrandomized Sobol' or Halton points, randomized Halton: −1 up to log factors on f of bounded
// Hardy–Krause variation (the Koksma–Hlawka bound with D* = O((log N)^s/N),
// [Kuipers & Niederreiter], [Niederreiter 1992]): analytic, smooth and C0 f; no tabulated rate
// for jumps (a curved one has infinite variation) or singular f. `note`/`source` name the set.
theoretical_rate low_discrepancy_rate(const integrand_class& f, std::string note,
                                      std::string source);

// How a shifted lattice's integrand is made periodic (docs/theory.md#lattice-periodizations).
struct lattice_periodizing {
  std::string_view name = "none";  // the `periodization` value
  // k: the integrand the rule sees has derivatives through order k that agree at 0 and 1 (−1: not
  // periodic; 0: the baker's map and c0; m − 1 for a Jacobian φ' vanishing to order m).
  int periodic_order = -1;
  // A change of variables weighting f(φ(x)) by ∏φ' (c0 … c3sin), not a map of the points.
  bool weighted = false;
};

// A randomly shifted rank-1 lattice rule: −1 on f with square-integrable mixed first derivatives
// (analytic, smooth, C0); with the baker's transform −2 on f with square-integrable mixed second
// derivatives (analytic, smooth; C0 stays −1), both up to N^ε ([Hickernell 2002];
// [Dick, Nuyens & Pillichshammer 2014]; [Dick, Kuo & Sloan 2013]); no tabulated rate for jumps
// or singular f. A weighted periodization of order k (φ' vanishing to order m = k + 1): −(k + 2)
// = −(m + 1) on analytic or smooth f (its Fourier coefficients decay as r(h)^−(m+1)), −1 on C0 f
// (mixed first derivatives only), none tabulated for jumps or singular f (g ~ x^((m+1)α+m) tames
// an endpoint singularity, but no rate is proven here).
theoretical_rate shifted_lattice_rate(const integrand_class& f, const lattice_periodizing& p);

// A scrambled Sobol' set that is no net: N ≠ 2^m, or the first point dropped. Smooth f: −1
// ([Owen 2022]); otherwise no tabulated rate.
theoretical_rate broken_net_rate(const integrand_class& f, std::string note);

}  // namespace quadmc
