// Composite left and right rectangle rules: one node at the left (right) end of each of n panels,
// weight h = 1/n.
//
// Use them as the baseline first-order rules: for f ∈ C¹ the error is at most (b − a)h·M₁/2,
// O(n⁻¹) (Burden & Faires, "Numerical Analysis", §4.4; the per-panel error is h²f′(ξ)/2). They
// are what a Riemann sum or a naive "sample every h" loop computes. Not for anything where
// accuracy matters: the midpoint rule costs the same and is second order.
#pragma once

#include "quadmc/core/errors.hpp"

#include <cstdint>
#include <string_view>

namespace quadmc {

enum class rectangle_side { left, right };

template <rectangle_side Side>
class rectangle_rule {
 public:
  class node_set {
   public:
    explicit node_set(std::uint64_t n) : n_(n), panels_(static_cast<double>(n)) {}
    std::uint64_t size() const noexcept { return n_; }
    // Left: k/n; right: (k + 1)/n, so the last right node is exactly 1.
    double node(std::uint64_t k) const noexcept {
      const std::uint64_t i = Side == rectangle_side::left ? k : k + 1;
      return static_cast<double>(i) / panels_;
    }
    double weight(std::uint64_t) const noexcept { return 1.0 / panels_; }

   private:
    std::uint64_t n_;
    double panels_;
  };

  std::string_view name() const noexcept {
    return Side == rectangle_side::left ? "composite left rectangle" : "composite right rectangle";
  }
  int order() const noexcept { return 1; }
  node_set nodes(std::uint64_t n) const {
    require(n >= 1, "n", n, "at least 1 panel");
    return node_set(n);
  }
};

using left_rectangle_rule = rectangle_rule<rectangle_side::left>;
using right_rectangle_rule = rectangle_rule<rectangle_side::right>;

}  // namespace quadmc
