// Test-only weighted point sets that are not tensor grids, so the tests of weighted_point_set.hpp
// and weighted_sum.hpp see a set with weights of both signs and a genuinely s-dimensional one:
//  - extrapolated_midpoint: (4·M_2n − M_n)/3, one Richardson step on the composite midpoint rule
//    (Burden & Faires, "Numerical Analysis", §4.5; the midpoint error has an expansion in even
//    powers of h = 1/n, so the h² terms cancel and the error is O(n⁻⁴)). 3n nodes in 1D: the 2n
//    nodes of M_2n with weight 4/3·1/(2n), then the n nodes of M_n with weight −1/3·1/n.
//  - fibonacci_lattice: the rank-1 lattice rule with N = F_k points z_i = ({i/N}, {i·F_{k−1}/N})
//    in 2D, weights 1/N (the Fibonacci lattices of Sloan & Joe, "Lattice Methods for Multiple
//    Integration"). It integrates e^{2πi h·x} exactly unless h·(1, F_{k−1}) ≡ 0 mod N.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/rules/weighted_point_set.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc::testing {

class extrapolated_midpoint {
 public:
  explicit extrapolated_midpoint(std::uint64_t n) : n_(n) {
    require(n >= 1, "n", n, "at least 1 panel");
  }
  std::uint64_t size() const noexcept { return 3 * n_; }
  std::size_t dimension() const noexcept { return 1; }
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    require_weighted_batch(1, size(), first, nodes, weights);
    const double fine = static_cast<double>(2 * n_);
    const double coarse = static_cast<double>(n_);
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const std::uint64_t p = first + i;
      if (p < 2 * n_) {
        nodes[i] = (static_cast<double>(p) + 0.5) / fine;
        weights[i] = 4.0 / (3.0 * fine);
      } else {
        nodes[i] = (static_cast<double>(p - 2 * n_) + 0.5) / coarse;
        weights[i] = -1.0 / (3.0 * coarse);
      }
    }
  }

 private:
  std::uint64_t n_;
};

class fibonacci_lattice {
 public:
  // N = F_k and the generator F_{k−1}; k ≥ 3 so that N ≥ 2, k ≤ 48 so that (N − 1)·F_{k−1} <
  // F_48·F_47 ≈ 1.4e19 < 2^64 and the residue below is exact.
  explicit fibonacci_lattice(unsigned k) {
    require(k >= 3 && k <= 48, "k", k, "a Fibonacci index in [3, 48]");
    std::uint64_t previous = 1;
    std::uint64_t current = 1;
    for (unsigned i = 2; i < k; ++i) {
      const std::uint64_t next = previous + current;
      previous = current;
      current = next;
    }
    n_ = current;
    generator_ = previous;
  }
  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return 2; }
  std::uint64_t generator() const noexcept { return generator_; }
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    require_weighted_batch(2, n_, first, nodes, weights);
    const double n = static_cast<double>(n_);
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const std::uint64_t p = first + i;
      const std::uint64_t residue = p * generator_ % n_;  // exact: see the constructor
      nodes[2 * i] = static_cast<double>(p) / n;
      nodes[2 * i + 1] = static_cast<double>(residue) / n;
      weights[i] = 1.0 / n;
    }
  }

 private:
  std::uint64_t n_ = 0;
  std::uint64_t generator_ = 0;
};

}  // namespace quadmc::testing
