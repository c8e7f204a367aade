// Composite Gauss–Legendre rule: m nodes per panel at the zeros of the Legendre polynomial P_m,
// mapped to each of n panels (m·n nodes in all).
//
// Use it for smooth integrands when evaluations are expensive: m nodes integrate polynomials of
// degree 2m − 1 exactly and the error is (b − a)H^{2m}(m!)⁴/((2m + 1)((2m)!)³)·f^{(2m)}(ξ) with
// panel width H (Davis & Rabinowitz, "Methods of Numerical Integration", 2nd ed., §2.7, eq.
// 2.7.12, summed over the panels). Not for integrands with kinks or jumps (no better than the
// midpoint rule there) or for smooth periodic ones (the trapezoid rule is better).
//
// Nodes and weights are Boost.Math's: boost::math::quadrature::gauss<double, M> holds tables for
// M = 7, 10, 15, 20, 25, 30 and computes the others once from the zeros of P_M. M is a template
// parameter in Boost; a scene chooses m at run time, so the supported m are a fixed list,
// gauss_legendre_rule::supported_points, and any other m is rejected.
#pragma once

#include "quadmc/core/errors.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace quadmc {

class gauss_legendre_rule {
 public:
  static constexpr std::array<unsigned, 10> supported_points = {2, 3, 4, 5, 7, 10, 15, 20, 25, 30};
  static constexpr unsigned max_points = 30;

  class node_set {
   public:
    node_set(const gauss_legendre_rule& rule, std::uint64_t n)
        : m_(rule.m_),
          n_(n),
          panels_(static_cast<double>(n)),
          unit_nodes_(rule.unit_nodes_),
          unit_weights_(rule.unit_weights_) {}
    std::uint64_t size() const noexcept { return n_ * m_; }
    // Node j of panel p = k / m sits at (p + τ_j)/n with τ_j = (1 + ξ_j)/2 ∈ (0, 1).
    double node(std::uint64_t k) const noexcept {
      const std::uint64_t panel = k / m_;
      const std::uint64_t j = k - panel * m_;
      return (static_cast<double>(panel) + unit_nodes_[j]) / panels_;
    }
    double weight(std::uint64_t k) const noexcept { return unit_weights_[k % m_] / panels_; }

   private:
    // A copy of the tables (480 bytes, one per axis and call) so that a node set never dangles.
    std::uint64_t m_;
    std::uint64_t n_;
    double panels_;
    std::array<double, max_points> unit_nodes_;
    std::array<double, max_points> unit_weights_;
  };

  explicit gauss_legendre_rule(unsigned m) : m_(m) {
    bool supported = false;
    for (unsigned p : supported_points) supported |= (p == m);
    require(supported, "m (Gauss–Legendre points per panel)", m,
            "one of 2, 3, 4, 5, 7, 10, 15, 20, 25, 30 (Boost.Math fixes the node count at "
            "compile time)");
    switch (m) {
      case 2:
        fill<2>();
        break;
      case 3:
        fill<3>();
        break;
      case 4:
        fill<4>();
        break;
      case 5:
        fill<5>();
        break;
      case 7:
        fill<7>();
        break;
      case 10:
        fill<10>();
        break;
      case 15:
        fill<15>();
        break;
      case 20:
        fill<20>();
        break;
      case 25:
        fill<25>();
        break;
      case 30:
        fill<30>();
        break;
      default:
        break;  // unreachable: rejected above
    }
    name_ = fmt::format("composite Gauss–Legendre m = {}", m);
  }

  unsigned points() const noexcept { return m_; }
  std::string_view name() const noexcept { return name_; }
  int order() const noexcept { return 2 * static_cast<int>(m_); }
  node_set nodes(std::uint64_t n) const {
    require(n >= 1, "n", n, "at least 1 panel");
    require(n <= std::numeric_limits<std::uint64_t>::max() / m_, "n", n,
            "at most (2^64 − 1)/m panels (the m·n nodes must be countable in 64 bits)");
    return node_set(*this, n);
  }

  // The nodes and weights on [0, 1] of a single panel, ascending.
  double unit_node(unsigned j) const noexcept { return unit_nodes_[j]; }
  double unit_weight(unsigned j) const noexcept { return unit_weights_[j]; }

 private:
  // Boost stores the non-negative half of the symmetric nodes ξ (ξ = 0 first when M is odd) with
  // weights on [−1, 1]; we unfold them to ascending nodes τ = (1 + ξ)/2 on [0, 1] with weights w/2.
  template <unsigned M>
  void fill() {
    using gauss = boost::math::quadrature::gauss<double, M>;
    const auto& xi = gauss::abscissa();
    const auto& w = gauss::weights();
    const unsigned half = M / 2;   // nodes strictly right of 0
    const unsigned first = M % 2;  // index of the first positive ξ in Boost's table
    for (unsigned i = 0; i < half; ++i) {
      const double x = xi[first + i];
      const double wi = w[first + i];
      unit_nodes_[half - 1 - i] = (1.0 - x) / 2.0;
      unit_weights_[half - 1 - i] = wi / 2.0;
      unit_nodes_[M - half + i] = (1.0 + x) / 2.0;
      unit_weights_[M - half + i] = wi / 2.0;
    }
    if (first == 1) {
      unit_nodes_[half] = 0.5;
      unit_weights_[half] = w[0] / 2.0;
    }
  }

  unsigned m_;
  std::array<double, max_points> unit_nodes_{};
  std::array<double, max_points> unit_weights_{};
  std::string name_;
};

}  // namespace quadmc
