// The weighted-point-set interface: a cubature rule Q(f) = Σ_{i<N} w_i f(t_i) on the unit cube,
// given as N nodes t_i ∈ [0,1]^s and weights w_i of either sign, generated in batches by index.
//
// Use it to add a deterministic rule in s dimensions — a tensor product (tensor_product_grid.hpp),
// a sparse grid (Smolyak: s-dimensional nodes, weights of both signs), an extrapolated or
// combination rule, a lattice or other QMC rule with equal weights 1/N — without a kernel of its
// own: weighted_sum.hpp maps the nodes to the integrand's box, evaluates f in batches, and sums
// w_i f_i in parallel with a compensated sum, bitwise the same for any thread count. Not for
// random point sets whose error is estimated from the points (sampling/point_set.hpp and the
// Monte Carlo estimators), and not for adaptive rules whose nodes depend on f (romberg.hpp).
//
// Contract:
//  - generate(first, nodes, weights) writes points [first, first + count), count =
//    weights.size(), row-major: nodes[i*s + j] = coordinate j of node first + i, weights[i] its
//    weight. nodes.size() must be count·s and [first, first + count) inside [0, N); a set checks
//    that once per batch (require_weighted_batch) and throws invalid_argument otherwise.
//  - Every coordinate is in the closed cube [0, 1]: unlike a Monte Carlo point set, a rule's
//    nodes may lie on the boundary (trapezoid, Simpson and rectangle nodes include 0 or 1), so an
//    integrand that cannot be evaluated there needs an open rule (midpoint, Gauss–Legendre).
//  - Weights are finite and refer to the unit cube: a rule exact for constants has Σ w_i = 1, and
//    the kernel multiplies by the box volume Π(b_j − a_j) once. Either sign is allowed.
//  - A node and its weight are a pure function of (the set's parameters, the index): batches may
//    be generated in any order and on any thread with bitwise identical results. The index order
//    is the summation order, so it is part of the rule's result, not an implementation detail.
//  - size() = N ≥ 1 and dimension() = s ≥ 1 are fixed at construction.
//
// Optional fast path (box_mapped_point_set): the kernel maps node t to x_j = a_j + (b_j − a_j)·t_j
// (cube_to_box below), s multiply-adds per point. A set whose nodes repeat — a tensor grid reuses
// each axis's m coordinates m^(s−1) times — may precompute that map once per call: mapped(map)
// returns a generator whose generate(first, x, weights) writes the box coordinates map(j, t_j)
// directly, bitwise equal to generating t and mapping it (tested in
// tests/rules/tensor_product_grid_test.cpp), so the fast path never changes a result. (Measured
// with callgrind on tensor Simpson, s = 2, a cheap integrand: 52 instructions per point with it,
// 66 through the kernel's map.)
//
// Rounding: the kernel's sum of the terms w_i f_i has an error of about (2 + log2 256)·ε·Σ|w_i f_i|
// (pairwise within a batch, Neumaier across batches: Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., §4.2–4.3), and an error δ in every f value moves Q by at most
// Σ|w_i|·max|δ| (triangle inequality). For positive weights Σ|w_i| = Σ w_i = 1; with weights of
// both signs it is larger (5/3 for the extrapolated midpoint rule (4M_2n − M_n)/3; it can grow
// with the level of a Smolyak grid), and so is the rounding error relative to |Q(f)|.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/integrand.hpp"

#include <fmt/format.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

template <class P>
concept weighted_point_set = requires(const P& p, std::uint64_t first, std::span<double> nodes,
                                      std::span<double> weights) {
  { p.size() } -> std::convertible_to<std::uint64_t>;
  { p.dimension() } -> std::convertible_to<std::size_t>;
  { p.generate(first, nodes, weights) } -> std::same_as<void>;
};

// The map of the unit cube onto a box, x_j = lower_j + width_j·t_j with width_j = upper_j −
// lower_j: the one formula every path of the kernel uses, so that a set's precomputed map
// (mapped) and the kernel's own give the same bits. Holds copies: the kernel builds it once per
// call from the integrand's box.
struct cube_to_box {
  std::vector<double> lower;
  std::vector<double> width;

  explicit cube_to_box(const box& domain) : lower(domain.lower), width(domain.lower.size()) {
    for (std::size_t j = 0; j < lower.size(); ++j) width[j] = domain.upper[j] - domain.lower[j];
  }
  std::size_t dimension() const noexcept { return lower.size(); }
  double operator()(std::size_t j, double t) const noexcept { return lower[j] + width[j] * t; }
  // Maps a row-major batch of nodes in place, one axis at a time: a_j and w_j stay in registers
  // (a store to nodes could alias lower or width, which would force two reloads per coordinate).
  void apply(std::span<double> nodes) const noexcept {
    const std::size_t s = lower.size();
    for (std::size_t j = 0; j < s; ++j) {
      const double a = lower[j];
      const double w = width[j];
      for (std::size_t i = j; i < nodes.size(); i += s) nodes[i] = a + w * nodes[i];
    }
  }
};

// A set that can write box coordinates directly (see "Optional fast path" above).
template <class P>
concept box_mapped_point_set = weighted_point_set<P> &&
    requires(const P& p, const cube_to_box& map, std::uint64_t first, std::span<double> x,
             std::span<double> weights) {
  { p.mapped(map).generate(first, x, weights) } -> std::same_as<void>;
};

// Validates a generate() request of a set with N points in s dimensions: nodes.size() =
// weights.size()·s, and the batch inside [0, N). Once per batch, not per point; the message is
// formatted only when a check fails (it would cost more than the batch's points otherwise).
inline void require_weighted_batch(std::size_t s, std::uint64_t n, std::uint64_t first,
                                   std::span<const double> nodes, std::span<const double> weights) {
  if (nodes.size() % s != 0 || nodes.size() / s != weights.size()) [[unlikely]] {
    throw invalid_argument("batch nodes size", quote(nodes.size()),
                           fmt::format("weights size × dimension = {} × {} = {}", weights.size(), s,
                                       weights.size() * s));
  }
  if (first > n || weights.size() > n - first) [[unlikely]] {
    throw invalid_argument(
        "batch first point", quote(first),
        fmt::format("a batch of {} points inside [0, N) with N = {}", weights.size(), n));
  }
}

}  // namespace quadmc
