// Composite midpoint rule: one node at the centre of each of n panels, weight h = 1/n.
//
// Use it for C² integrands when the end points must not be evaluated (an integrable singularity
// at a or b), and as the tensor-product building block whose error is half the trapezoid's with
// the opposite sign: I − M = +(b − a)h²f″(ξ)/24 (Burden & Faires, "Numerical Analysis", §4.4,
// Thm 4.6). Not for smooth periodic integrands (the trapezoid rule is the one that converges
// exponentially there) or for high accuracy on smooth f (Simpson, Gauss–Legendre).
#pragma once

#include "quadmc/core/errors.hpp"

#include <cstdint>
#include <string_view>

namespace quadmc {

class midpoint_rule {
 public:
  class node_set {
   public:
    explicit node_set(std::uint64_t n)
        : n_(n), panels_(static_cast<double>(n)), weight_(1.0 / panels_) {}
    std::uint64_t size() const noexcept { return n_; }
    // (k + ½)/n, divided rather than multiplied by 1/n so that the node is correctly rounded.
    double node(std::uint64_t k) const noexcept { return (static_cast<double>(k) + 0.5) / panels_; }
    // 1/n, divided once here rather than per node (same quotient, same bits).
    double weight(std::uint64_t) const noexcept { return weight_; }

   private:
    std::uint64_t n_;
    double panels_;
    double weight_;
  };

  std::string_view name() const noexcept { return "composite midpoint"; }
  int order() const noexcept { return 2; }
  node_set nodes(std::uint64_t n) const {
    require(n >= 1, "n", n, "at least 1 panel");
    return node_set(n);
  }
};

}  // namespace quadmc
