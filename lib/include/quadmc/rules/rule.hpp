// The `rule` concept: a composite 1D quadrature rule described by its nodes and weights.
//
// Use it to write one kernel for every rule: the tensor product (tensor_product_grid.hpp,
// integrated by tensor_product.hpp) asks a rule for the node set of n panels and never needs to
// know which rule it is. A rule that is not a product of 1D rules is a weighted point set instead
// (weighted_point_set.hpp). Not for adaptive rules
// whose nodes depend on f (Romberg stops when converged, so it has its own entry point in
// romberg.hpp).
//
// A rule with n panels on the unit interval [0, 1] is Q_n(f) = Σ_k w_k f(t_k), k < m(n): its
// `node_set` gives m(n), t_k and w_k lazily (no m-sized table, so a 1D rule with 2^30 panels
// allocates nothing). On [a, b] the nodes are a + (b − a)·t_k and the weights (b − a)·w_k.
// Every rule here has positive weights summing to 1 — the tensor-product error bound relies on
// that (error_bounds.hpp). Source: the composite rules of Burden & Faires, "Numerical Analysis",
// §4.3–4.4, written as weighted sums as in Davis & Rabinowitz, "Methods of Numerical
// Integration", §2.
#pragma once

#include <concepts>
#include <cstdint>
#include <string_view>

namespace quadmc {

// The nodes and weights of one rule for a fixed number of panels, on [0, 1], nodes ascending.
template <class N>
concept node_set = requires(const N& q, std::uint64_t k) {
  { q.size() } -> std::same_as<std::uint64_t>;
  { q.node(k) } -> std::same_as<double>;
  { q.weight(k) } -> std::same_as<double>;
};

// A composite rule. nodes(n) validates n at the API boundary (n ≥ 1, Simpson: n even, node count
// representable) and throws quadmc::invalid_argument otherwise. order() is r in the error
// O(h^r) = O(n^−r) for f smooth enough (rectangle 1, midpoint/trapezoid 2, Simpson 4,
// Gauss–Legendre 2m).
template <class R>
concept rule = requires(const R& r, std::uint64_t n) {
  { r.name() } -> std::convertible_to<std::string_view>;
  { r.order() } -> std::same_as<int>;
  { r.nodes(n) } -> node_set;
};

}  // namespace quadmc
