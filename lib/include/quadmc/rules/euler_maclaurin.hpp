// The Euler–Maclaurin expansion of a composite rule's error, and the error it predicts on an
// integrand whose end-point derivatives are known (integrand_info::endpoint_derivatives).
//
// Every composite rule of rules/ repeats one panel rule — nodes τᵢ ∈ [0, 1], weights wᵢ summing
// to 1 — over panels of width H (the rule's panel: one panel for rectangle, midpoint, trapezoid and
// Gauss–Legendre, a pair for Simpson). For G smooth on [0, 1] and H = 1/(number of panels)
// ([Lyness & Ninham 1967], the offset-trapezoid expansion; [Stoer & Bulirsch, §3.3] for the
// trapezoid rule; derivation in docs/theory.md#euler-maclaurin-expansion):
//
//   ∫G − Q(G) = Σ_{j≥1} c_j·H^j·[G⁽ʲ⁻¹⁾(1) − G⁽ʲ⁻¹⁾(0)],   c_j = −(1/j!)·Σᵢ wᵢ·B_j(τᵢ),
//
// B_j the Bernoulli polynomials. So trapezoid −1/12, +1/720; midpoint +1/24, −7/5760; Simpson
// (H the width of a pair) 0, −1/2880, +1/96768; m-point Gauss–Legendre 0 for j < 2m and
// c_2m = (m!)⁴/((2m + 1)((2m)!)³), the constant of its Peano-kernel error [Davis & Rabinowitz,
// §2.7]. A kink of G at c (G continuous, G⁽ᵏ⁾ jumping by [G⁽ᵏ⁾]) adds, by the same integration by
// parts on each side of c,
//
//   Σ_{j≥2} d_j(θ)·H^j·[G⁽ʲ⁻¹⁾](c),   d_j(θ) = (1/j!)·Σᵢ wᵢ·P_j(τᵢ − θ),
//
// θ = c/H − ⌊c/H⌋ the kink's place in its panel, P_j(x) = B_j(x − ⌊x⌋). For a product
// f = Re[σ·Π g_j(x_j)] the tensor rule is Re[σ·Π Q(g_j)] exactly, so its error is
// Re[σ·(Π I_j − Π(I_j − E_j))], summed without cancellation as Σ_j Π_{k<j}(I_k −
// E_k)·E_j·Π_{k>j}I_k.
//
// The series is only asymptotic: a pole z of g at distance d = |Im z| from the axis adds the
// coarse-grid term the series does not show (derivation in docs/theory.md#coarse-grid-term;
// [Trefethen & Weideman 2014, §5], [Davis & Rabinowitz, §2.9]). By Poisson summation each offset
// lattice Σ_k H·g(a + (k + τ)H) differs from the line integral of r/(x − z) by
// ±2πi·r·Σ_{k≥1} e^(∓2πikτ)·Q^k, Q = e^(±2πi(z − a)/H) (upper sign for Im z > 0), |Q| = e^(−2πd/H);
// the panel rule (nodes τᵢ, weights wᵢ) combines them with ŵ(k) = Σᵢ wᵢ·e^(−2πikτᵢ):
//
//   Q(g) − ∫g ∋ ω·(±2πi·r)·Σ_{k≥1} ŵ(±k)·Q^k,
//
// ŵ(k) = 1 for the trapezoid (and the rectangles), (−1)^k for the midpoint, 1/3 + (2/3)(−1)^k for
// Simpson (H the pair: its leading term is −(1/3)·e^(−2πd/H), the trapezoid's e^(−2πd/h) on the
// half-width h = H/2 being its square). ω = 1 for a pole above the interior, 0 outside, 1/2 above
// an end (a Stokes line: exact when the pair's residues are imaginary, i.e. g is even about that
// end, as 1/(1 + x²) about 0 — then that end's series has no term the pole feeds). Near an end's
// vertical, within 3·√(dH/π), the weight passes from 0 to 1 [Berry 1989]: the term is then known
// only to its own size and counts as uncertainty of the prediction (next_change).
//
// Use it where a rule's measured error is to be explained (the analysis compares the two cell
// by cell, analysis/convergence_table.hpp). The prediction keeps the first two non-vanishing terms
// of every axis and the coarse-grid term of every pole the factor lists; the third term says how
// far to trust it (an asymptotic series errs by about its first omitted term). Not for f with jumps
// (rules/jump_error_envelope.hpp bounds those), an endpoint singularity (the expansion has terms in
// H^(1+α)), or analytic f whose complex singularities are not listed (endpoint_factor::poles):
// there the third-term test is the only guard against a coarse-grid term.
#pragma once

#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/rule.hpp"

#include <fmt/format.h>
#include <boost/math/special_functions/bernoulli.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace quadmc {

// The expansion is carried to H^euler_maclaurin_orders: one order more than the derivatives of
// endpoint_factor (term j uses G⁽ʲ⁻¹⁾).
inline constexpr int euler_maclaurin_orders = static_cast<int>(endpoint_derivative_count);

// B_j(t) = Σ_k C(j, k)·B_k·t^(j−k) (B₁ = −1/2, odd B_k = 0 beyond), in long double: for j ≤ 24 and
// t ∈ [0, 1] the terms are at most ten times the value, so it keeps 17 digits. `magnitude`, when
// given, receives Σ_k |C(j, k)·B_k·t^(j−k)|: the scale of its rounding (at a zero of B_j the value
// itself is rounding noise and says nothing about it).
inline long double bernoulli_polynomial(int j, long double t, long double* magnitude = nullptr) {
  long double sum = 0.0L, size = 0.0L;
  long double binomial = 1.0L;  // C(j, k)
  for (int k = 0; k <= j; ++k) {
    long double b = 0.0L;
    if (k == 0) {
      b = 1.0L;
    } else if (k == 1) {
      b = -0.5L;
    } else if (k % 2 == 0) {
      b = boost::math::bernoulli_b2n<long double>(k / 2);
    }
    if (b != 0.0L) {
      const long double term = binomial * b * std::pow(t, static_cast<long double>(j - k));
      sum += term;
      size += std::abs(term);
    }
    binomial = binomial * static_cast<long double>(j - k) / static_cast<long double>(k + 1);
  }
  if (magnitude != nullptr) *magnitude = size;
  return sum;
}

// P_j(x) = B_j(x − ⌊x⌋), the periodic Bernoulli function.
inline long double periodic_bernoulli(int j, long double x) {
  return bernoulli_polynomial(j, x - std::floor(x));
}

// The coefficients of one composite rule: c_j of the expansion above and the kink kernel d_j(θ).
class euler_maclaurin_rule {
 public:
  // From a rule of rule.hpp: its node set for `unit_panels` panels is the panel rule (Simpson: 2,
  // the pair; every other rule: 1), read in double, summed in long double. A coefficient is 0
  // when its sum is within 64ε of the magnitude of the sum's terms (Σᵢ wᵢ·Σ_k |C(j, k)B_k
  // τᵢ^(j−k)|, which bounds the rounding of the double nodes and of the sum: the rule's symmetry or
  // exactness makes it vanish: midpoint's odd orders, Gauss–Legendre's below 2m), and known when
  // the double-rounded tables leave it accurate to 1e-9 relative (m-point Gauss–Legendre loses
  // digits like the cancellation of its 2m-th order term; large m is not known).
  template <rule R>
  static euler_maclaurin_rule of(const R& r, std::uint64_t unit_panels) {
    euler_maclaurin_rule out;
    out.unit_panels_ = unit_panels;
    const auto set = r.nodes(unit_panels);
    for (std::uint64_t k = 0; k < set.size(); ++k) {
      out.node_.push_back(set.node(k));
      out.weight_.push_back(set.weight(k));
    }
    long double factorial = 1.0L;
    constexpr long double eps = std::numeric_limits<double>::epsilon();
    for (int j = 1; j <= euler_maclaurin_orders; ++j) {
      factorial *= static_cast<long double>(j);
      long double sum = 0.0L, magnitude = 0.0L;
      for (std::size_t i = 0; i < out.node_.size(); ++i) {
        long double size = 0.0L;
        sum += out.weight_[i] * bernoulli_polynomial(j, out.node_[i], &size);
        magnitude += std::abs(out.weight_[i]) * size;
      }
      const bool zero = std::abs(sum) <= 64.0L * eps * magnitude;
      out.coefficient_[j] = zero ? 0.0L : -sum / factorial;
      out.known_[j] = zero || 16.0L * eps * magnitude <= 1e-9L * std::abs(sum);
    }
    return out;
  }

  std::uint64_t unit_panels() const noexcept { return unit_panels_; }
  long double coefficient(int j) const noexcept { return coefficient_[j]; }
  bool known(int j) const noexcept { return known_[j]; }
  // The first order with a non-zero coefficient (the rule's order r for the rules here), or 0.
  int order() const noexcept {
    for (int j = 1; j <= euler_maclaurin_orders; ++j) {
      if (coefficient_[j] != 0.0L || !known_[j]) return j;
    }
    return 0;
  }
  // ŵ(k) = Σᵢ wᵢ·e^(−2πikτᵢ): the panel rule's k-th Fourier coefficient, the weight of the k-th
  // harmonic of a pole's coarse-grid term (docs/theory.md#coarse-grid-term).
  std::complex<long double> fourier_weight(long long k) const {
    constexpr long double two_pi = 6.283185307179586476925286766559L;
    std::complex<long double> sum(0.0L, 0.0L);
    for (std::size_t i = 0; i < node_.size(); ++i) {
      // The phase modulo 2π from k·τ reduced to [0, 1) first: cos of a large argument loses it.
      long double turn = static_cast<long double>(k) * node_[i];
      turn -= std::floor(turn);
      sum += weight_[i] * std::polar(1.0L, -two_pi * turn);
    }
    return sum;
  }
  // d_j(θ) of a kink at relative position θ ∈ [0, 1) of its panel.
  long double kink_coefficient(int j, long double theta) const {
    long double sum = 0.0L, factorial = 1.0L;
    for (int k = 2; k <= j; ++k) factorial *= static_cast<long double>(k);
    for (std::size_t i = 0; i < node_.size(); ++i) {
      sum += weight_[i] * periodic_bernoulli(j, node_[i] - theta);
    }
    return sum / factorial;
  }

 private:
  std::uint64_t unit_panels_ = 1;
  std::vector<long double> node_, weight_;
  std::array<long double, euler_maclaurin_orders + 1> coefficient_{};
  std::array<bool, euler_maclaurin_orders + 1> known_{};
};

// What the expansion predicts for one grid: Q − I from the first two non-vanishing terms of every
// axis, and how much the third moves it.
struct euler_maclaurin_value {
  double error = std::numeric_limits<double>::quiet_NaN();  // predicted Q − I (signed)
  // (|P₃ − P₂| + U)/|P₂|, U the coarse-grid terms whose weight is not known (near an end's
  // vertical): how far to trust the prediction.
  double next_change = std::numeric_limits<double>::quiet_NaN();
  // The part of `error` the poles' coarse-grid terms make (signed; 0 without poles).
  double coarse_grid = 0.0;
};

// The prediction for one rule on one integrand (any number of panels n per axis).
class euler_maclaurin_prediction {
 public:
  // nullopt when f has no end-point data, or a term among the first three of an axis would need a
  // coefficient that is not known (Gauss–Legendre with large m).
  static std::optional<euler_maclaurin_prediction> make(euler_maclaurin_rule rule,
                                                        const integrand_info& f) {
    if (!f.endpoint_derivatives || f.endpoint_derivatives->factors.size() != f.dimension()) {
      return std::nullopt;
    }
    euler_maclaurin_prediction out;
    out.rule_ = std::move(rule);
    out.data_ = *f.endpoint_derivatives;
    out.domain_ = f.domain;
    for (const endpoint_factor& g : out.data_.factors) {
      std::vector<int> orders;
      for (int j = 1; j <= euler_maclaurin_orders && orders.size() < 3; ++j) {
        const bool kinked = j >= 2 && has_jump(g, j - 1);
        const bool ends = !vanishes(g, j - 1);
        if (ends && !out.rule_.known(j)) return std::nullopt;
        if (kinked || (ends && out.rule_.coefficient(j) != 0.0L)) orders.push_back(j);
      }
      // A rule whose order lies beyond the expansion cannot show a vanishing term.
      if (out.rule_.order() == 0 || out.rule_.order() + 4 > euler_maclaurin_orders) {
        return std::nullopt;
      }
      out.orders_.push_back(std::move(orders));
    }
    return out;
  }

  // The order j of the first non-vanishing term over all axes (the error is O(H^j)); 0 when every
  // term through H^euler_maclaurin_orders vanishes on every axis (f periodic with all its
  // derivatives: exponential convergence).
  int leading_order() const noexcept {
    int order = 0;
    for (const auto& o : orders_) {
      if (!o.empty() && (order == 0 || o.front() < order)) order = o.front();
    }
    return order;
  }
  // The rule's own first order (2 for midpoint and trapezoid, 4 for Simpson, 2m for Gauss).
  int rule_order() const noexcept { return rule_.order(); }
  const euler_maclaurin_rule& rule() const noexcept { return rule_; }

  // Which end-point terms below the leading order vanished, e.g. "f⁽³⁾(1) − f⁽³⁾(0) = 0 (the H⁴
  // term)"; empty when none did.
  std::string vanished() const {
    std::string out;
    const int lead = leading_order();
    const int last = lead == 0 ? euler_maclaurin_orders : lead - 1;
    for (std::size_t a = 0; a < data_.factors.size(); ++a) {
      for (int j = rule_.order(); j <= last; ++j) {
        if (rule_.coefficient(j) == 0.0L || has_jump(data_.factors[a], j - 1)) continue;
        if (!vanishes(data_.factors[a], j - 1)) continue;
        const std::string g =
            data_.factors.size() == 1 ? "f" : fmt::format("g{}", subscript(a + 1));
        const std::string k = superscript(j - 1);
        const std::string entry =
            fmt::format("{0}⁽{1}⁾({2}) − {0}⁽{1}⁾({3}) = 0 (the H{4} term)", g, k, domain_.upper[a],
                        domain_.lower[a], superscript(j));
        out += out.empty() ? entry : "; " + entry;
        if (lead == 0) break;  // every order vanishes: one line per axis says it
      }
    }
    return out;
  }

  // The leading term in words: for s = 1 its coefficient and end-point difference, e.g.
  // "(1/96768)·H⁶·[f⁽⁵⁾(1) − f⁽⁵⁾(0)] = 1.55e-04·H⁶"; for s > 1 the order only.
  std::string leading_term() const {
    const int j = leading_order();
    if (j == 0) return "no term through H" + superscript(euler_maclaurin_orders);
    if (data_.factors.size() != 1 || !data_.factors[0].kinks.empty()) {
      return fmt::format("the H{} terms of the axes, combined exactly", superscript(j));
    }
    const endpoint_factor& g = data_.factors[0];
    const long double c = rule_.coefficient(j);
    const std::complex<double> delta = g.at_upper[j - 1] - g.at_lower[j - 1];
    const double width = domain_.upper[0] - domain_.lower[0];
    const double value = static_cast<double>(c) * delta.real() / std::pow(width, j - 1);
    const std::string head =
        fmt::format("{}·H{}·[f⁽{}⁾({}) − f⁽{}⁾({})]", rational_text(c), superscript(j),
                    superscript(j - 1), domain_.upper[0], superscript(j - 1), domain_.lower[0]);
    // On a very narrow or very wide box the x-derivatives overflow; the unit variable's do not.
    if (!std::isfinite(value) || value == 0.0) return head;
    return fmt::format("{} = {:.3g}·H{}", head, value, superscript(j));
  }

  // The prediction for n panels per axis (n a valid panel count of the rule).
  euler_maclaurin_value at(std::uint64_t n) const {
    using cplx = std::complex<long double>;
    const long double h =
        static_cast<long double>(rule_.unit_panels()) / static_cast<long double>(n);
    const std::size_t s = data_.factors.size();
    std::vector<cplx> integral(s), two(s), three(s), series(s);
    std::vector<long double> unknown(s, 0.0L);
    for (std::size_t a = 0; a < s; ++a) {
      const endpoint_factor& g = data_.factors[a];
      const long double width = domain_.upper[a] - domain_.lower[a];
      integral[a] = cplx(g.integral.real(), g.integral.imag());
      // Terms in the unit variable, times the width: ∫g dx − Q(g) = w·(∫G dt − Q(G)).
      cplx sum(0.0L, 0.0L);
      for (std::size_t t = 0; t < orders_[a].size(); ++t) {
        sum += term(g, a, orders_[a][t], h, n) * width;
        if (t < 2) two[a] = sum;
        three[a] = sum;
      }
      series[a] = two[a];
      // The poles' coarse-grid terms, ∫g − Q(g) ∋ −(Q(g) − ∫g), in x units.
      const std::optional<coarse_grid_part> coarse = coarse_grid_term(g, a, h * width);
      if (!coarse) {
        euler_maclaurin_value none;
        none.next_change = std::numeric_limits<double>::infinity();
        return none;
      }
      two[a] -= coarse->error;
      three[a] -= coarse->error;
      unknown[a] = coarse->unknown;
    }
    // I − Q = Re[σ·(Π I − Π(I − E))] = Re[σ·Σ_a Π_{b<a}(I_b − E_b)·E_a·Π_{b>a} I_b].
    const auto difference = [&](const std::vector<cplx>& e) {
      cplx total(0.0L, 0.0L), left(1.0L, 0.0L);
      for (std::size_t a = 0; a < s; ++a) {
        cplx right(1.0L, 0.0L);
        for (std::size_t b = a + 1; b < s; ++b) right *= integral[b];
        total += left * e[a] * right;
        left *= integral[a] - e[a];
      }
      const cplx scale(data_.scale.real(), data_.scale.imag());
      return (scale * total).real();
    };
    const long double p2 = difference(two), p3 = difference(three);
    // An unknown coarse-grid term u_a of axis a moves I − Q by about u_a·|scale·Π_{b≠a} I_b|.
    long double doubt = 0.0L;
    for (std::size_t a = 0; a < s; ++a) {
      if (unknown[a] == 0.0L) continue;
      long double others = std::abs(data_.scale);
      for (std::size_t b = 0; b < s; ++b) {
        if (b != a) others *= std::abs(integral[b]);
      }
      doubt += unknown[a] * others;
    }
    euler_maclaurin_value out;
    out.error = static_cast<double>(-p2);  // Q − I
    out.next_change = p2 != 0.0L ? static_cast<double>((std::abs(p3 - p2) + doubt) / std::abs(p2))
                                 : std::numeric_limits<double>::infinity();
    out.coarse_grid = static_cast<double>(-p2 + difference(series));
    return out;
  }

  // Whether any factor lists a pole (the prediction then carries a coarse-grid term).
  bool has_poles() const noexcept {
    return std::any_of(data_.factors.begin(), data_.factors.end(),
                       [](const endpoint_factor& g) { return !g.poles.empty(); });
  }

  // The coarse-grid term in words, e.g. "coarse-grid term of the poles 0 ± 1i (d = 1, above the
  // end x = 0: weight 1/2) ≈ −1.05·e^(−2πd/H)" (s = 1: the leading harmonic of the poles nearest
  // the axis, its sign that of Q − I); empty without poles.
  std::string coarse_grid_text() const {
    if (!has_poles()) return {};
    if (data_.factors.size() != 1) {
      return "coarse-grid terms e^(−2πd/H) of the factors' poles (d their distance from the axis)";
    }
    const endpoint_factor& g = data_.factors[0];
    double d = std::numeric_limits<double>::infinity();
    for (const simple_pole& p : g.poles) d = std::min(d, std::abs(p.location.imag()));
    // The leading harmonic k (the first with ŵ(k) ≠ 0) and its coefficient: Q − I ≈
    // C·e^(−2πkd/H) summed over the poles at distance d, phases at H = the whole interval.
    std::string where;
    long double coefficient = 0.0L;
    int k = 0;
    for (int harmonic = 1; harmonic <= 8 && k == 0; ++harmonic) {
      for (const simple_pole& p : g.poles) {
        if (std::abs(p.location.imag()) != d) continue;
        const auto [weight, exact] = stokes_weight(p, 0);
        (void)exact;
        const int sign = p.location.imag() > 0 ? 1 : -1;
        const std::complex<long double> w = rule_.fourier_weight(sign * harmonic);
        if (std::abs(w) <= 1e-12L) continue;
        k = harmonic;
        const std::complex<long double> r(p.residue.real(), p.residue.imag());
        coefficient +=
            (weight * std::complex<long double>(0.0L, sign * 6.283185307179586476925286766559L) *
             r * w)
                .real();
        if (where.empty()) {
          where = weight == 1.0L   ? "above the interior: weight 1"
                  : weight == 0.5L ? "above an end: weight 1/2"
                                   : "outside the interval: weight 0";
        }
      }
    }
    const double re = g.poles.front().location.real();
    return fmt::format(
        "coarse-grid term of the poles {} ± {}i (distance d = {} from [{}, {}], {}) "
        "≈ {:.3g}·e^(−2π{}d/H)",
        re, d, d, domain_.lower[0], domain_.upper[0], where, static_cast<double>(coefficient),
        k == 1 ? std::string() : std::to_string(k));
  }

 private:
  // G⁽ᵏ⁾(1) − G⁽ᵏ⁾(0) vanishes: within 1e-10 of the end values of orders k − 1, k and k + 1 (the
  // closed forms of functions/endpoint_derivatives.hpp give structural zeros exactly; this absorbs
  // the rounding of two equal values, and of a zero computed as a tiny number, e.g. f‴(1) of
  // e^{sin 2πx} with sin 2π ≈ −2.4e-16, judged by the size of its neighbours).
  static bool vanishes(const endpoint_factor& g, int k) {
    const auto at = static_cast<std::size_t>(k);
    double scale = 0.0;
    for (std::size_t m = at == 0 ? 0 : at - 1; m <= at + 1 && m < g.at_lower.size(); ++m) {
      scale = std::max({scale, std::abs(g.at_lower[m]), std::abs(g.at_upper[m])});
    }
    return std::abs(g.at_upper[at] - g.at_lower[at]) <= 1e-10 * scale;
  }
  // What a pole adds: Q(g) − ∫g (x units) where its weight is known, and the size of what is not.
  struct coarse_grid_part {
    std::complex<long double> error{0.0L, 0.0L};
    long double unknown = 0.0L;
  };

  // ω of docs/theory.md#coarse-grid-term for panel width `panel` (x units; 0: the verdict only)
  // and whether it is exact: 1 above the interior, 0 outside, 1/2 on an end's vertical (exact for
  // an imaginary residue); within 3·√(dH/π) of a vertical but off it, not known.
  std::pair<long double, bool> stokes_weight(const simple_pole& p, std::size_t axis,
                                             long double panel = 0.0L) const {
    const long double lower = domain_.lower[axis], upper = domain_.upper[axis];
    const long double x = p.location.real(), d = std::abs(p.location.imag());
    const long double zone = 3.0L * std::sqrt(d * panel / 3.141592653589793238462643383279L);
    const long double on = 1e-12L * (upper - lower);
    const bool imaginary = std::abs(p.residue.real()) <= 1e-12 * std::abs(p.residue);
    for (const long double end : {lower, upper}) {
      if (std::abs(x - end) <= on) return {0.5L, imaginary};
      if (std::abs(x - end) < zone) return {0.5L, false};
    }
    return {x > lower && x < upper ? 1.0L : 0.0L, true};
  }

  // Σ over g's poles of ω·(±2πi·r)·Σ_{k≥1} ŵ(±k)·Q^k, summed until |Q|^k < 1e-30 (nullopt when
  // that takes more than 2^16 harmonics: a grid so coarse that H ≫ 10⁴·d).
  std::optional<coarse_grid_part> coarse_grid_term(const endpoint_factor& g, std::size_t axis,
                                                   long double panel) const {
    using cplx = std::complex<long double>;
    constexpr long double two_pi = 6.283185307179586476925286766559L;
    coarse_grid_part out;
    for (const simple_pole& p : g.poles) {
      const auto [weight, exact] = stokes_weight(p, axis, panel);
      if (weight == 0.0L) continue;
      const long double sign = p.location.imag() > 0 ? 1.0L : -1.0L;
      const long double d = std::abs(p.location.imag());
      const long double x = (p.location.real() - domain_.lower[axis]) / panel;
      // Q = e^(±2πi(z − a)/H): modulus e^(−2πd/H), phase ±2π·x (x reduced modulo 1).
      const long double decay = std::exp(-two_pi * d / panel);
      if (decay == 0.0L) continue;
      const long double turn = x - std::floor(x);
      const cplx q = std::polar(decay, sign * two_pi * turn);
      const long double harmonics = std::ceil(69.0L / (two_pi * d / panel));  // |Q|^k < 1e-30
      if (!(harmonics <= 65536.0L)) return std::nullopt;
      cplx sum(0.0L, 0.0L), power(1.0L, 0.0L);
      for (long long k = 1; k <= static_cast<long long>(harmonics); ++k) {
        power *= q;
        sum += rule_.fourier_weight(static_cast<long long>(sign) * k) * power;
      }
      const cplx r(p.residue.real(), p.residue.imag());
      const cplx term = cplx(0.0L, sign * two_pi) * r * sum;
      if (exact) {
        out.error += weight * term;
      } else {
        out.unknown += std::abs(term);
      }
    }
    return out;
  }

  static bool has_jump(const endpoint_factor& g, int k) {
    for (const derivative_jump& kink : g.kinks) {
      if (static_cast<std::size_t>(k) < kink.jumps.size() &&
          kink.jumps[static_cast<std::size_t>(k)] != 0.0) {
        return true;
      }
    }
    return false;
  }

  // Term j of axis a in the unit variable: c_j·H^j·ΔG⁽ʲ⁻¹⁾ + Σ_kinks d_j(θ)·H^j·[G⁽ʲ⁻¹⁾].
  std::complex<long double> term(const endpoint_factor& g, std::size_t a, int j, long double h,
                                 std::uint64_t n) const {
    using cplx = std::complex<long double>;
    const auto k = static_cast<std::size_t>(j - 1);
    const std::complex<double> delta = g.at_upper[k] - g.at_lower[k];
    cplx value = rule_.coefficient(j) * cplx(delta.real(), delta.imag());
    const long double width = domain_.upper[a] - domain_.lower[a];
    for (const derivative_jump& kink : g.kinks) {
      if (k >= kink.jumps.size() || kink.jumps[k] == 0.0) continue;
      // The kink's place in its panel: t_c·(panels) with t_c = (c − lower)/w and
      // panels = n/unit_panels, reduced modulo 1 in long double.
      const long double t = (static_cast<long double>(kink.location) - domain_.lower[a]) / width;
      const long double panels = static_cast<long double>(n) / rule_.unit_panels();
      long double theta = t * panels;
      theta -= std::floor(theta);
      value += rule_.kink_coefficient(j, theta) * cplx(kink.jumps[k].real(), kink.jumps[k].imag());
    }
    return value * std::pow(h, static_cast<long double>(j));
  }

  static std::string superscript(std::size_t k) {
    static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    const std::string text = std::to_string(k);
    std::string out;
    for (char c : text) out += digits[c - '0'];
    return out;
  }
  static std::string superscript(int k) { return superscript(static_cast<std::size_t>(k)); }
  static std::string subscript(std::size_t k) {
    static const char* digits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    const std::string text = std::to_string(k);
    std::string out;
    for (char c : text) out += digits[c - '0'];
    return out;
  }
  // c as p/q when a continued fraction finds q ≤ 10⁸ within 1e-12 relative (every Newton–Cotes
  // coefficient), else in scientific notation.
  static std::string rational_text(long double c) {
    const long double target = std::abs(c);
    long double x = target;
    long double p0 = 0.0L, q0 = 1.0L, p1 = 1.0L, q1 = 0.0L;
    for (int step = 0; step < 20; ++step) {
      const long double a = std::floor(x);
      const long double p2 = a * p1 + p0, q2 = a * q1 + q0;
      p0 = p1, q0 = q1, p1 = p2, q1 = q2;
      if (q1 > 1e8L) break;
      if (std::abs(p1 / q1 - target) <= 1e-12L * target) {
        return fmt::format("({}{:.0f}/{:.0f})", c < 0 ? "−" : "", static_cast<double>(p1),
                           static_cast<double>(q1));
      }
      if (x == a) break;
      x = 1.0L / (x - a);
    }
    return fmt::format("{:.6g}", static_cast<double>(c));
  }

  euler_maclaurin_rule rule_;
  separable_derivatives data_;
  box domain_;
  std::vector<std::vector<int>> orders_;  // per axis: the first (up to) three non-vanishing orders
};

}  // namespace quadmc
