// Composite Simpson rule: n + 1 equally spaced nodes (n even), weights h/3·(1, 4, 2, 4, …, 4, 1)
// with node spacing h = 1/n.
//
// Use it for C⁴ integrands: I − S = −(b − a)h⁴f⁽⁴⁾(ξ)/180 with h the node spacing (Burden &
// Faires, "Numerical Analysis", §4.4, Thm 4.4; with panel width H = 2h the constant is 1/2880).
// It is exact for cubics. Not for integrands with a kink or a jump (it drops to the rate of the
// simplest rules, O(n⁻²) resp. O(n⁻¹), with a larger constant), and an odd n is rejected rather
// than rounded: a silently changed n would shift every point of a convergence plot.
#pragma once

#include "quadmc/core/errors.hpp"

#include <cstdint>
#include <limits>
#include <string_view>

namespace quadmc {

class simpson_rule {
 public:
  class node_set {
   public:
    // The three weights h/3·{1, 4, 2} are divided once here, not per node (a tensor grid asks
    // for a weight per point); same quotients, same bits.
    explicit node_set(std::uint64_t n)
        : n_(n),
          panels_(static_cast<double>(n)),
          end_weight_(1.0 / (3.0 * panels_)),
          odd_weight_(4.0 / (3.0 * panels_)),
          even_weight_(2.0 / (3.0 * panels_)) {}
    std::uint64_t size() const noexcept { return n_ + 1; }
    double node(std::uint64_t k) const noexcept { return static_cast<double>(k) / panels_; }
    double weight(std::uint64_t k) const noexcept {
      return (k == 0 || k == n_) ? end_weight_ : ((k & 1U) != 0 ? odd_weight_ : even_weight_);
    }

   private:
    std::uint64_t n_;
    double panels_;
    double end_weight_, odd_weight_, even_weight_;
  };

  // A display name for messages; scenes name the method in methods/tensor_rules.cpp.
  std::string_view name() const noexcept { return "composite Simpson"; }
  int order() const noexcept { return 4; }
  node_set nodes(std::uint64_t n) const {
    require(n >= 2 && n % 2 == 0, "n", n, "an even number of panels ≥ 2 (Simpson pairs panels)");
    require(n < std::numeric_limits<std::uint64_t>::max(), "n", n,
            "fewer than 2^64 − 1 panels (the n + 1 nodes must be countable in 64 bits)");
    return node_set(n);
  }
};

}  // namespace quadmc
