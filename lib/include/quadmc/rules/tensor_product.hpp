// Tensor-product quadrature over a box: integrate(f, rule, n), the entry point of every rule of
// this layer, 1D included.
//
// Q(f) = Π(b_j − a_j) · Σ_{k_1…k_s} w_{k_1}⋯w_{k_s} f(a_1 + (b_1 − a_1)t_{k_1}, …), the product of
// a 1D rule with m nodes along each of the s axes, N = m^s evaluations
// (docs/theory.md#tensor-products; [Ramamoorthi 2009, §1.2]). Use it for smooth integrands in a few
// dimensions; its error is O(N^(−r/s)) for a rule of order r, so past s ≈ 4 Monte Carlo and QMC win
// (the curse of dimensionality, docs/theory.md#tensor-products), and a jump across a non-axis
// surface gives only O(N^(−1/s)) (docs/theory.md#jumps). Not for a rule that is not a product of
// one 1D rule (hand a weighted point set to weighted_sum() instead).
//
// It is weighted_sum (weighted_sum.hpp: batches of 256, chunks of 2^14 folded in order, the
// accumulators of enum summation) over tensor_product_grid (tensor_product_grid.hpp: the odometer,
// the product weights, the tabulated nodes); this file adds only the rule's n and the
// plain-callable form.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/rule.hpp"
#include "quadmc/rules/rule_result.hpp"
#include "quadmc/rules/tensor_product_grid.hpp"
#include "quadmc/rules/weighted_sum.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <span>
#include <type_traits>

namespace quadmc {

// ∫ f over f.info().domain by the tensor product of `rule` with n panels per axis. 1D is s = 1.
// threads = 0 uses every core; the result is bitwise the same for every thread count.
// `accumulate` chooses how the N terms w·f are summed (core/summation.hpp, enum summation); the
// default is pairwise per batch, Neumaier across batches (weighted_sum.hpp). summation::naive
// runs on one thread whatever `threads` says (a left-to-right sum is one chain of adds).
// Throws invalid_argument for bad n, domain or grid size, non_finite_value if f returns NaN/±inf
// (the message names the point). error_estimate is NaN: a fixed rule has no a-posteriori
// estimate (see error_bounds.hpp for a-priori bounds, romberg.hpp for an estimate).
template <integrand F, rule R>
rule_result integrate(const F& f, const R& rule, std::uint64_t n, unsigned threads = 1,
                      summation accumulate = summation::pairwise) {
  const integrand_info info = detail::checked_integrand_info(f);
  const tensor_product_grid grid(rule.nodes(n), f.dimension());
  return detail::checked_weighted_sum(f, info, grid, threads, accumulate);
}

namespace detail {

// A plain callable double(double) on [a, b] seen as a 1D integrand, so that the convenience form
// below runs the same kernel (one inlined call per point, no type erasure).
template <class G>
class interval_function {
 public:
  interval_function(const G& g, double a, double b) : g_(&g) {
    info_.name = "function";
    info_.domain = box{{a}, {b}};
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = (*g_)(x[i]);
  }
  const integrand_info& info() const noexcept { return info_; }

 private:
  const G* g_;
  integrand_info info_;
};

}  // namespace detail

// ∫_a^b g(x) dx for a plain callable, by the same kernel (the batch integrand path above is the
// one the runner uses; this form is for tests and quick use).
template <class G, rule R>
requires std::is_invocable_r_v<double, const G&, double> rule_result
integrate(const G& g, double a, double b, const R& rule, std::uint64_t n, unsigned threads = 1,
          summation accumulate = summation::pairwise) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b,
          fmt::format("≥ a = {} (swap the bounds for a reversed interval)", quote(a)));
  return integrate(detail::interval_function<G>(g, a, b), rule, n, threads, accumulate);
}

}  // namespace quadmc
