// A-priori error envelopes of the composite rules and of Romberg on integrands with jumps: the
// bound a convergence ladder on a discontinuous integrand is judged against, instead of a slope.
//
// Use it for a deterministic rule on an integrand whose integrand_info::separable_factors
// describe its jumps (step, Genz discontinuous in any s, the disk and half-space in 1D). Why not
// a slope: a rule's error on a jump is set by where the jump falls in its cell, which is not
// monotone in n (a jump at c whose binary expansion has a run of ones keeps the midpoint error on
// a dyadic ladder flat over as many doublings as the run is long); theory gives a bound O(h) that
// holds at every n, not a rate every ladder follows. Not for jumps across curved or oblique
// surfaces (the disk and half-space for s ≥ 2 carry no factors): a count of the cells the surface
// cuts gives O(h) there too, but the cells' errors cancel and the measured error falls faster,
// so that envelope would pass every run and say nothing. Not an a-posteriori estimate.
//
// The argument, for one factor g on [a, b] and a composite rule whose elementary cell (a panel;
// for Simpson a pair of panels) has width H and positive weights summing to H; E = I − Q:
//   g = φ + Σ_i σ_i·U_i, σ_i = g(c_i+) − g(c_i−), U_i the unit step at c_i taking the value
//   λ_i ∈ [0, 1] at c_i itself (g(c_i) lies between the two limits), and φ continuous, smooth
//   between the c_i with |φ⁽ᵏ⁾| ≤ M_k there. E is linear, so |E(g)| is at most the sum of
//   (1) the jump term: |E(U_c)| ≤ K·H for every c and λ (K below), so ≤ K·H·Σ_i|J_i|;
//   (2) the cut cells: on a closed cell C holding some c_i, φ is Lipschitz with constant M₁ and
//       the rule is exact on constants, so with x_C the cell's centre
//       |E_C(φ)| = |∫_C (φ − φ(x_C)) − Σ_k w_k (φ(t_k) − φ(x_C))| ≤ M₁(∫_C|x − x_C| + Σ_k w_k|t_k −
//       x_C|) = L·M₁·H², L = 1/4 + Σ_j ŵ_j|τ_j − 1/2| (τ_j, ŵ_j the nodes and weights of the cell
//       mapped to [0, 1]); a point lies in at most two closed cells: ≤ 2·(number of jumps) cells;
//   (3) every other cell: φ is as smooth as g there, and the composite bounds of error_bounds.hpp
//       are sums of per-cell bounds, so the uncut cells together stay under the bound for all of
//       [a, b] with M_r, r the rule's order. Where M_r is unknown or r > 4 (Gauss–Legendre with
//       m ≥ 3), the Taylor bound: a rule exact through degree k − 1 (any k ≤ r) errs on a cell
//       by at most (M_k/k!)(∫_C|x − x_C|ᵏ + Σ w_k|t_k − x_C|ᵏ) = (M_k/k!)·T_k·H^{k+1}, T_k =
//       2⁻ᵏ/(k + 1) + Σ_j ŵ_j|τ_j − 1/2|ᵏ (expand g − its Taylor polynomial of degree k − 1 at x_C,
//       on which E vanishes), (b − a)·T_k·H^k·M_k/k! in all, with the largest known k ≥ 1.
//   envelope(n) = K·H·Σ|J_i| + 2·(number of jumps)·L·M₁·H² + smooth(n).
// An end-point jump (g(b) ≠ g(b−), g(a) ≠ g(a+)) costs the weight of a node there times |J|:
// right rectangle H, trapezoid H/2, Simpson H/6, none for the others, each ≤ K·H, the same term.
//
// The jump constant K = sup over θ = (c − x_left)/H ∈ [0, 1] and λ of |E(U_c)|/H. The cells right
// of the one holding c integrate U_c exactly (it is 1 there), those left of it give 0, so
// E(U_c)/H = d(θ, λ) = (1 − θ) − Σ_{τ_j > θ} ŵ_j − λ·Σ_{τ_j = θ} ŵ_j, and at a cell boundary
// (θ = 0, shared with the left neighbour's θ = 1) d = ŵ(τ = 0)·(1 − λ) − λ·ŵ(τ = 1). Between nodes
// d falls with slope −1 and it steps at the nodes, so the sup is one of the one-sided limits at
// a node, reached with the jump on that node:
//   left rectangle  τ = 0:            d = 1 − θ inside, 1 − λ on a node          K = 1
//   right rectangle τ = 1:            d = −θ inside, −λ on a node                 K = 1
//   midpoint        τ = 1/2:          d = −θ, 1 − θ either side, 1/2 − λ on it   K = 1/2
//                   (a jump at a panel end costs nothing; on the node |E| = |J|·H/2 exactly)
//   trapezoid       τ = 0, 1 (1/2):   d = 1/2 − θ inside, 1/2 − λ on a node      K = 1/2
//   Simpson         pair H = 2h, τ = 0, 1/2, 1 (1/6, 4/6, 1/6): d = 1/6 − θ, then 1/3 − 2λ/3 on
//                   the middle node, 5/6 − θ, 1/6 − λ/3 at the boundary          K = 1/3
//                   (|E| ≤ |J|·H/3 = 2|J|h/3, h = (b − a)/n the node spacing; on an odd node)
//   Gauss–Legendre  τ_j ∈ (0, 1), C_j = ŵ_1 + … + ŵ_j: d = C_j − θ on (τ_j, τ_{j+1}), 0 at the
//                   boundary: K = max_j max(C_j − τ_j, τ_j − C_{j−1}), below max_j ŵ_j by the
//                   Chebyshev–Markov–Stieltjes separation C_{j−1} < τ_j < C_j (Szegő, "Orthogonal
//                   Polynomials", Thm 3.41.1); m = 2: 1/(2√3) ≈ 0.289, m = 3: ŵ_2/2 = 2/9.
// jump_defect_constant computes this sup from the cell's nodes and weights, for any rule.
//
// Romberg: R(k, k) = Σ_j c_j·T(2ʲ), j = 0…k, Σ c_j = 1 (the extrapolation is linear in the
// trapezoid values, romberg.hpp), so |E(R)| ≤ Σ_j |c_j|·envelope_trapezoid(2ʲ). Rigorous, not
// tight: its jump term tends to 1.277·|J|·h (h = (b − a)/2ᵏ) where the trapezoid's is |J|·h/2.
//
// Separable f = Π_j g_j on a box, tensor rule Q = ⊗Q_j: I − Q = Σ_j Q₁⋯Q_{j−1}(I_j −
// Q_j)I_{j+1}⋯I_s (the identity of error_bounds.hpp), so |E| ≤ Σ_j Π_{i<j} q_i·e_j·Π_{i>j}|I_i|,
// e_j the envelope of factor j, |Q_i g_i| ≤ q_i = min(L_i·M_{0,i}, |I_i| + e_i) (positive weights
// summing to L_i).
//
// The envelope is exact arithmetic; the caller adds the rounding of the sums (the analysis adds
// the rounding level of rounding_floor.hpp before it compares).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/error_bounds.hpp"
#include "quadmc/rules/romberg.hpp"
#include "quadmc/rules/rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace quadmc {

// Panels per elementary cell: Simpson's weights repeat over pairs of panels.
template <rule R>
std::uint64_t panels_per_cell(const R&) noexcept {
  return 1;
}
inline std::uint64_t panels_per_cell(const simpson_rule&) noexcept {
  return 2;
}

// The nodes and weights of one elementary cell mapped to [0, 1] (weights summing to 1), ascending.
struct cell_nodes {
  std::vector<double> node;
  std::vector<double> weight;
};

template <rule R>
cell_nodes elementary_cell(const R& rule) {
  const auto q = rule.nodes(panels_per_cell(rule));
  cell_nodes cell;
  for (std::uint64_t k = 0; k < q.size(); ++k) {
    cell.node.push_back(q.node(k));
    cell.weight.push_back(q.weight(k));
  }
  return cell;
}

// K of |E(U_c)| ≤ K·H (the sup of |d| in the header).
template <rule R>
double jump_defect_constant(const R& rule) {
  const cell_nodes cell = elementary_cell(rule);
  double at_left = 0.0, at_right = 0.0;  // weights of nodes at θ = 0 and θ = 1
  double largest = 0.0;
  for (std::size_t j = 0; j < cell.node.size(); ++j) {
    const double tau = cell.node[j];
    if (tau == 0.0) {
      at_left += cell.weight[j];
      continue;
    }
    if (tau == 1.0) {
      at_right += cell.weight[j];
      continue;
    }
    // Interior node: d just right of it (the node counts on the left, λ = 1) and just left of
    // it (λ = 0); weights of nodes strictly right of τ and of those at or right of it.
    double right = 0.0;
    for (std::size_t i = j + 1; i < cell.node.size(); ++i) right += cell.weight[i];
    largest = std::max(largest, std::abs((1.0 - tau) - right));
    largest = std::max(largest, std::abs((1.0 - tau) - right - cell.weight[j]));
  }
  // The boundary: d ranges over [−ŵ(τ = 1), ŵ(τ = 0)], the limits θ → 1− and θ → 0+.
  return std::max({largest, at_left, at_right});
}

// L of the cut-cell term L·M₁·H²: ∫₀¹|θ − 1/2| dθ + Σ ŵ_j|τ_j − 1/2|.
template <rule R>
double cut_cell_constant(const R& rule) {
  const cell_nodes cell = elementary_cell(rule);
  double sum = 0.25;
  for (std::size_t j = 0; j < cell.node.size(); ++j) {
    sum += cell.weight[j] * std::abs(cell.node[j] - 0.5);
  }
  return sum;
}

// T_k/k! of the Taylor bound (header): the cell error is ≤ that·M_k·H^{k+1} for k ≤ order.
template <rule R>
double taylor_cell_constant(const R& rule, int k) {
  require(k >= 1 && k <= rule.order(), "k", k,
          fmt::format("1 ≤ k ≤ the order {} of {} (exact through degree k − 1)", rule.order(),
                      rule.name()));
  const cell_nodes cell = elementary_cell(rule);
  double sum = std::ldexp(1.0, -k) / (k + 1.0);
  for (std::size_t j = 0; j < cell.node.size(); ++j) {
    sum += cell.weight[j] * std::pow(std::abs(cell.node[j] - 0.5), k);
  }
  double factorial = 1.0;
  for (int i = 2; i <= k; ++i) factorial *= i;
  return sum / factorial;
}

// Bound of the rule's error on the smooth pieces of g over all of [a, b] (part (3) of the
// header); empty when no M_k with 1 ≤ k ≤ min(order, 4) is known.
template <rule R>
std::optional<double> smooth_part_bound(const R& rule, const piecewise_smooth_factor& g, double a,
                                        double b, std::uint64_t n) {
  const int order = bound_derivative_order(rule);
  if (order < static_cast<int>(g.derivative_bound.size()) &&
      g.derivative_bound[static_cast<std::size_t>(order)]) {
    return error_bound(rule, a, b, n, *g.derivative_bound[static_cast<std::size_t>(order)]);
  }
  const double cell = (b - a) * static_cast<double>(panels_per_cell(rule)) / static_cast<double>(n);
  for (int k = std::min(rule.order(), 4); k >= 1; --k) {
    const auto& mk = g.derivative_bound[static_cast<std::size_t>(k)];
    if (!mk) continue;
    return (b - a) * taylor_cell_constant(rule, k) * std::pow(cell, k) * *mk;
  }
  return std::nullopt;
}

// The envelope of one factor on [a, b] with n panels (the header's formula); empty when a bound
// it needs (M₁ with jumps present, a smooth-part M_k) is not known.
template <rule R>
std::optional<double> factor_error_envelope(const R& rule, const piecewise_smooth_factor& g,
                                            double a, double b, std::uint64_t n) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b, fmt::format("≥ a = {}", quote(a)));
  (void)rule.nodes(n);  // validates n (≥ 1; Simpson: even)
  const std::optional<double> smooth = smooth_part_bound(rule, g, a, b, n);
  if (!smooth) return std::nullopt;
  if (g.jumps.empty()) return *smooth;
  const std::optional<double>& m1 = g.derivative_bound[1];
  if (!m1) return std::nullopt;
  double total_jump = 0.0;
  for (const jump_discontinuity& jump : g.jumps) {
    require(std::isfinite(jump.size) && jump.size >= 0.0, "jump size", jump.size,
            "a finite |g(c+) − g(c−)| ≥ 0");
    total_jump += jump.size;
  }
  const double cell = (b - a) * static_cast<double>(panels_per_cell(rule)) / static_cast<double>(n);
  const double cut_cells = 2.0 * static_cast<double>(g.jumps.size());
  return jump_defect_constant(rule) * cell * total_jump +
         cut_cells * cut_cell_constant(rule) * *m1 * cell * cell + *smooth;
}

namespace detail {

// The product bound of the header from each factor's envelope e_j, |I_j| and L_j·M_{0,j}.
struct factor_bounds {
  double envelope;
  double integral_abs;  // |I_j|, or L_j·M_{0,j} when the integral is not given
  double sum_abs;       // bound on |Q_j g_j|
};

inline std::optional<double> product_envelope(const std::vector<factor_bounds>& factors) {
  double total = 0.0;
  for (std::size_t j = 0; j < factors.size(); ++j) {
    double term = factors[j].envelope;
    for (std::size_t i = 0; i < j; ++i) term *= factors[i].sum_abs;
    for (std::size_t i = j + 1; i < factors.size(); ++i) term *= factors[i].integral_abs;
    total += term;
  }
  return total;
}

// |I_j| and the bound on |Q_j g_j| from the factor's metadata and its envelope e; empty when
// neither the integral nor M₀ is known.
inline std::optional<factor_bounds> bounds_of(const piecewise_smooth_factor& g, double width,
                                              double e) {
  const bool integral_known = std::isfinite(g.integral);
  if (!g.derivative_bound[0] && !integral_known) return std::nullopt;
  // +∞ for a bound that is unknown, so that min() takes the known one. (Plain doubles: GCC 12 at
  // -O1 took a std::optional<double> here for "maybe uninitialized".)
  constexpr double unknown = std::numeric_limits<double>::infinity();
  const double by_max = g.derivative_bound[0] ? width * *g.derivative_bound[0] : unknown;
  const double by_integral = integral_known ? std::abs(g.integral) : unknown;
  factor_bounds out;
  out.envelope = e;
  out.integral_abs = integral_known ? by_integral : by_max;
  out.sum_abs = integral_known ? std::min(by_integral + e, by_max) : by_max;
  return out;
}

inline bool has_jump(const integrand_info& info) {
  return std::any_of(info.separable_factors.begin(), info.separable_factors.end(),
                     [](const piecewise_smooth_factor& g) { return !g.jumps.empty(); });
}

}  // namespace detail

// The envelope of the tensor product of `rule` with n panels per axis on a separable f with at
// least one jump. Empty when f has no separable factors (one per axis), no jump, or a bound the
// envelope needs is unknown: the caller then keeps the slope verdict.
template <rule R>
std::optional<double> jump_error_envelope(const R& rule, const integrand_info& info,
                                          std::uint64_t n) {
  const std::size_t s = info.dimension();
  if (info.separable_factors.size() != s || s == 0 || !detail::has_jump(info)) return std::nullopt;
  require_integration_box(info.domain);
  std::vector<detail::factor_bounds> factors;
  for (std::size_t j = 0; j < s; ++j) {
    const double a = info.domain.lower[j], b = info.domain.upper[j];
    const std::optional<double> e = factor_error_envelope(rule, info.separable_factors[j], a, b, n);
    if (!e) return std::nullopt;
    const auto bounds = detail::bounds_of(info.separable_factors[j], b - a, *e);
    if (!bounds) return std::nullopt;
    factors.push_back(*bounds);
  }
  return detail::product_envelope(factors);
}

// c_j of R(k, k) = Σ_j c_j·T(2ʲ), j = 0…levels, from romberg.hpp's recurrence
// R(i, j) = R(i, j−1) + (R(i, j−1) − R(i−1, j−1))/(4ʲ − 1), R(i, 0) = T(2ⁱ).
inline std::vector<double> romberg_coefficients(unsigned levels) {
  require(levels <= romberg_max_levels, "levels", levels, "at most 40");
  // row[i] holds the coefficients of R(i, j) for the current column j, each over T(2⁰…2ⁱ).
  std::vector<std::vector<double>> row(levels + 1);
  for (unsigned i = 0; i <= levels; ++i) {
    row[i].assign(i + 1, 0.0);
    row[i][i] = 1.0;
  }
  double factor = 1.0;
  for (unsigned j = 1; j <= levels; ++j) {
    factor *= 4.0;
    // R(i, j) for i from the top down, so that R(i−1, j−1) is still the previous column's.
    for (unsigned i = levels; i >= j; --i) {
      std::vector<double> next = row[i];
      for (unsigned t = 0; t < row[i - 1].size(); ++t) {
        next[t] += (row[i][t] - row[i - 1][t]) / (factor - 1.0);
      }
      for (unsigned t = static_cast<unsigned>(row[i - 1].size()); t < next.size(); ++t) {
        next[t] += row[i][t] / (factor - 1.0);
      }
      row[i] = std::move(next);
    }
  }
  return row[levels];
}

// The envelope of Romberg's R(k, k) on 2^levels panels of a 1D f with a jump: Σ_j |c_j| times
// the trapezoid envelope on 2ʲ panels. Empty for s ≠ 1 and as for jump_error_envelope.
inline std::optional<double> romberg_jump_error_envelope(const integrand_info& info,
                                                         unsigned levels) {
  if (info.dimension() != 1) return std::nullopt;
  const std::vector<double> c = romberg_coefficients(levels);
  double total = 0.0;
  for (unsigned j = 0; j <= levels; ++j) {
    const std::optional<double> e =
        jump_error_envelope(trapezoid_rule{}, info, std::uint64_t{1} << j);
    if (!e) return std::nullopt;
    total += std::abs(c[j]) * *e;
  }
  return total;
}

}  // namespace quadmc
