// Composite trapezoid rule: n + 1 equally spaced nodes, weights h/2, h, …, h, h/2 (h = 1/n).
//
// Use it for smooth periodic integrands over a full period, where it converges exponentially
// (Trefethen & Weideman, "The exponentially convergent trapezoidal rule", SIAM Review 56, 2014,
// Thm 3.2), and as the base of Romberg extrapolation (romberg.hpp). For general C² integrands the
// error is I − T = −(b − a)h²f″(ξ)/12 (Burden & Faires, "Numerical Analysis", §4.4, Thm 4.5),
// twice the midpoint rule's, so prefer midpoint or Simpson there. Not for integrands that cannot
// be evaluated at the end points.
#pragma once

#include "quadmc/core/errors.hpp"

#include <cstdint>
#include <limits>
#include <string_view>

namespace quadmc {

class trapezoid_rule {
 public:
  class node_set {
   public:
    // The two weights are divided once here, not per node; same quotients, same bits.
    explicit node_set(std::uint64_t n)
        : n_(n),
          panels_(static_cast<double>(n)),
          end_weight_(0.5 / panels_),
          inner_weight_(1.0 / panels_) {}
    std::uint64_t size() const noexcept { return n_ + 1; }
    // k/n by division: exactly 0 and 1 at the ends, correctly rounded inside.
    double node(std::uint64_t k) const noexcept { return static_cast<double>(k) / panels_; }
    double weight(std::uint64_t k) const noexcept {
      return (k == 0 || k == n_) ? end_weight_ : inner_weight_;
    }

   private:
    std::uint64_t n_;
    double panels_;
    double end_weight_, inner_weight_;
  };

  std::string_view name() const noexcept { return "composite trapezoid"; }
  int order() const noexcept { return 2; }
  node_set nodes(std::uint64_t n) const {
    require(n >= 1, "n", n, "at least 1 panel");
    require(n < std::numeric_limits<std::uint64_t>::max(), "n", n,
            "fewer than 2^64 − 1 panels (the n + 1 nodes must be countable in 64 bits)");
    return node_set(n);
  }
};

}  // namespace quadmc
