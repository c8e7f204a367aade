// The Genz–Malik cubature rule on a box in s ≥ 2 dimensions: a fully symmetric rule of degree 7
// with an embedded rule of degree 5 on a subset of its nodes, whose difference is the error
// estimate of h-adaptive cubature (adaptive_cubature.hpp), and the fourth divided differences
// that choose the axis to split ([Genz & Malik 1980]; the rule as tabulated in their 1983 paper
// and used by [cubature]'s hcubature and Cuba's Cuhre; [Berntsen, Espelid & Genz 1991]).
//
// Use it through genz_malik_cubature() (adaptive_cubature.hpp); on its own it integrates one box
// with (value, error estimate, split axis). Not for s = 1 (the rule is built for s ≥ 2; in 1D a
// Gauss–Kronrod pair is the analogue, as hcubature does) and not for large s: a region costs
// 2^s + 2s² + 2s + 1 evaluations (66 081 at s = 16), so beyond s ≈ 10 even one level of
// subdivision is expensive and Monte Carlo or QMC wins.
//
// Nodes on the reference cube [−1, 1]^s (a box with centre c and half-widths h maps u to c + h·u),
// in this index order (node(index) generates any one of them, so batches can start anywhere):
//   0                       the centre                                         weight w₁ (E: e₁)
//   1 + 4k + {0,1,2,3}      ∓λ₂e_k, then ∓λ₃e_k, axis k = 0…s−1               w₂, w₃   (e₂, e₃)
//   1 + 4s + 4p + {0…3}     (±λ₄e_i ± λ₄e_j) for pair p = (i < j), signs −−, +−, −+, ++   w₄ (e₄)
//   1 + 2s² + 2s + v        (±λ₅, …, ±λ₅), coordinate j negative when bit j of v is set   w₅ (0)
// with λ₂ = √(9/70), λ₃ = λ₄ = √(9/10), λ₅ = √(9/19) and, normalised to a box of volume 1,
//   w₁ = (12824 − 9120s + 400s²)/19683, w₂ = 980/6561, w₃ = (1820 − 400s)/19683,
//   w₄ = 200/19683, w₅ = 6859/(19683·2^s);
//   e₁ = (729 − 950s + 50s²)/729, e₂ = 245/486, e₃ = (265 − 100s)/1458, e₄ = 25/729
// (each set sums to 1: the rules integrate constants). Degree 7 means exact for every polynomial
// of total degree ≤ 7, degree 5 for ≤ 5 (tests/rules/genz_malik_rule_test.cpp checks both for
// s = 2…10, and that degree 8 and 6 are not exact, so the degrees are not higher than claimed).
//
// Error estimate: |Q₇ − Q₅|, the difference of the two rules, with no safety factor (what
// hcubature reports; Berntsen, Espelid & Genz's null-rule estimate is more conservative and is
// not what is measured here). It estimates the error of Q₅, so it usually over-estimates Q₇'s;
// it can be far too small when both rules miss a feature between their nodes (a narrow peak, a
// jump), which the reliability scene measures.
//
// Split axis: the axis k with the largest |D_k|, D_k = f(−λ₂e_k) + f(λ₂e_k) − 2f(0) −
// (λ₂²/λ₃²)(f(−λ₃e_k) + f(λ₃e_k) − 2f(0)), the fourth divided difference along k with the
// second-difference part cancelled (Genz & Malik): the lowest k among equal maxima.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace quadmc {

// 2^s nodes per region: beyond s = 40 one region alone exceeds 10^12 evaluations.
inline constexpr std::size_t genz_malik_max_dimension = 40;

// What the rule says about one region.
struct genz_malik_estimate {
  double value = 0.0;  // Q₇ over the region (times its volume)
  double error = 0.0;  // |Q₇ − Q₅|
  std::size_t split_axis = 0;
};

class genz_malik_rule {
 public:
  static constexpr double lambda2 = 0.358568582800318091990645;  // √(9/70)
  static constexpr double lambda3 = 0.948683298050513799599668;  // √(9/10)
  static constexpr double lambda4 = lambda3;
  static constexpr double lambda5 = 0.688247201611685297721629;  // √(9/19)

  explicit genz_malik_rule(std::size_t s) : s_(s) {
    require(s >= 2 && s <= genz_malik_max_dimension, "Genz–Malik dimension s", s,
            "between 2 and 40 (the rule is built for s ≥ 2; 2^s nodes per region)");
    const double d = static_cast<double>(s);
    w1_ = (12824.0 - 9120.0 * d + 400.0 * d * d) / 19683.0;
    w2_ = 980.0 / 6561.0;
    w3_ = (1820.0 - 400.0 * d) / 19683.0;
    w4_ = 200.0 / 19683.0;
    w5_ = 6859.0 / 19683.0 / std::ldexp(1.0, static_cast<int>(s));
    e1_ = (729.0 - 950.0 * d + 50.0 * d * d) / 729.0;
    e2_ = 245.0 / 486.0;
    e3_ = (265.0 - 100.0 * d) / 1458.0;
    e4_ = 25.0 / 729.0;
    for (std::size_t i = 0; i + 1 < s; ++i) {
      for (std::size_t j = i + 1; j < s; ++j) pairs_.emplace_back(i, j);
    }
  }

  std::size_t dimension() const noexcept { return s_; }

  // 2^s + 2s² + 2s + 1: the centre, 4 points on each axis, 4 per pair of axes, 2^s vertices.
  std::uint64_t points() const noexcept { return points_for(s_); }
  static constexpr std::uint64_t points_for(std::size_t s) noexcept {
    return (std::uint64_t{1} << s) + 2 * s * s + 2 * s + 1;
  }

  // Node `index` of the region (centre, half_width) in box coordinates, into x (s values).
  void node(std::uint64_t index, std::span<const double> centre, std::span<const double> half_width,
            std::span<double> x) const noexcept {
    for (std::size_t j = 0; j < s_; ++j) x[j] = centre[j];
    if (index == 0) return;
    std::uint64_t k = index - 1;
    if (k < 4 * s_) {
      const std::size_t axis = static_cast<std::size_t>(k / 4);
      const unsigned which = static_cast<unsigned>(k % 4);
      const double lambda = which < 2 ? lambda2 : lambda3;
      const double sign = which % 2 == 0 ? -1.0 : 1.0;
      x[axis] = centre[axis] + sign * lambda * half_width[axis];
      return;
    }
    k -= 4 * s_;
    if (k < 4 * pairs_.size()) {
      const auto [i, j] = pairs_[static_cast<std::size_t>(k / 4)];
      const unsigned signs = static_cast<unsigned>(k % 4);
      x[i] = centre[i] + ((signs & 1u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[i];
      x[j] = centre[j] + ((signs & 2u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[j];
      return;
    }
    k -= 4 * pairs_.size();
    for (std::size_t j = 0; j < s_; ++j) {
      const double sign = ((k >> j) & 1u) != 0 ? -1.0 : 1.0;
      x[j] = centre[j] + sign * lambda5 * half_width[j];
    }
  }

  // Nodes first, first + 1, … of one region into out (count rows of s, row-major): node() for a
  // run of indices, with the vertex coordinates c_j ± λ₅h_j computed once per call instead of per
  // node (a region is 2^s vertices and little else once s ≳ 6). The same doubles as node(), built
  // cheaper: an axis or pair node is the centre row copied with one or two coordinates set, and
  // vertex v is vertex v − 1 copied with only the coordinates whose bit changed set again (two
  // on average). Callgrind: 67 → 29 instructions per node in s = 8, where node generation was
  // the difference between genz_malik and hcubature per region.
  void nodes(std::uint64_t first, std::size_t count, std::span<const double> centre,
             std::span<const double> half_width, double* out) const noexcept {
    const std::uint64_t pair_first = 1 + 4 * s_;
    const std::uint64_t vertex_first = pair_first + 4 * pairs_.size();
    std::size_t i = 0;
    for (; i < count && first + i < vertex_first; ++i) {
      double* x = out + i * s_;
      copy_row(centre.data(), x);
      const std::uint64_t index = first + i;
      if (index == 0) continue;
      if (index < pair_first) {
        const std::uint64_t k = index - 1;
        const auto axis = static_cast<std::size_t>(k / 4);
        const auto which = static_cast<unsigned>(k % 4);
        const double lambda = which < 2 ? lambda2 : lambda3;
        const double sign = which % 2 == 0 ? -1.0 : 1.0;
        x[axis] = centre[axis] + sign * lambda * half_width[axis];
        continue;
      }
      const std::uint64_t k = index - pair_first;
      const auto [a, b] = pairs_[static_cast<std::size_t>(k / 4)];
      const auto signs = static_cast<unsigned>(k % 4);
      x[a] = centre[a] + ((signs & 1u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[a];
      x[b] = centre[b] + ((signs & 2u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[b];
    }
    if (i == count) return;
    double plus[genz_malik_max_dimension];
    double minus[genz_malik_max_dimension];
    for (std::size_t j = 0; j < s_; ++j) {
      plus[j] = centre[j] + lambda5 * half_width[j];
      minus[j] = centre[j] - lambda5 * half_width[j];
    }
    std::uint64_t v = first + i - vertex_first;
    {
      double* x = out + i * s_;
      for (std::size_t j = 0; j < s_; ++j) x[j] = ((v >> j) & 1u) != 0 ? minus[j] : plus[j];
      ++i;
      ++v;
    }
    for (; i < count; ++i, ++v) {
      double* x = out + i * s_;
      copy_row(x - s_, x);
      // Bits 0…t flip from v − 1 to v (t = the trailing zeros of v): set those coordinates.
      for (std::uint64_t changed = v ^ (v - 1); changed != 0; changed &= changed - 1) {
        const auto j = static_cast<std::size_t>(std::countr_zero(changed));
        x[j] = ((v >> j) & 1u) != 0 ? minus[j] : plus[j];
      }
    }
  }

  // s doubles from one row to the next. GCC makes a call to memcpy of std::copy_n (and of a
  // plain loop); below 5 doubles the call costs more than the copy, so those are spelled out.
  void copy_row(const double* from, double* to) const noexcept {
    switch (s_) {
      case 4:
        to[3] = from[3];
        [[fallthrough]];
      case 3:
        to[2] = from[2];
        [[fallthrough]];
      case 2:
        to[1] = from[1];
        to[0] = from[0];
        return;
      default:
        std::copy_n(from, s_, to);
    }
  }

  // Q₇, |Q₇ − Q₅| and the split axis from the region's values in node order (points() of them).
  // The sums over the 2s(s−1) pair nodes and the 2^s vertices are pairwise (error ε·log₂n·Σ|f|,
  // core/summation.hpp), so rounding does not grow with s beyond the rule's own cancellation
  // (w₁ and w₃ are negative for s ≥ 2 and 5).
  genz_malik_estimate combine(std::span<const double> f, double volume) const noexcept {
    const double f0 = f[0];
    double sum2 = 0.0;
    double sum3 = 0.0;
    genz_malik_estimate out;
    double largest = -1.0;
    constexpr double ratio = (lambda2 * lambda2) / (lambda3 * lambda3);
    for (std::size_t k = 0; k < s_; ++k) {
      const double inner = f[1 + 4 * k] + f[2 + 4 * k];
      const double outer = f[3 + 4 * k] + f[4 + 4 * k];
      sum2 += inner;
      sum3 += outer;
      const double difference = std::abs(inner - 2.0 * f0 - ratio * (outer - 2.0 * f0));
      if (difference > largest) {
        largest = difference;
        out.split_axis = k;
      }
    }
    const std::size_t pair_first = 1 + 4 * s_;
    const std::size_t vertex_first = pair_first + 4 * pairs_.size();
    const double sum4 = pairwise_sum(f.subspan(pair_first, 4 * pairs_.size()));
    const double sum5 = pairwise_sum(f.subspan(vertex_first, std::size_t{1} << s_));
    const double q7 = volume * (w1_ * f0 + w2_ * sum2 + w3_ * sum3 + w4_ * sum4 + w5_ * sum5);
    const double q5 = volume * (e1_ * f0 + e2_ * sum2 + e3_ * sum3 + e4_ * sum4);
    out.value = q7;
    out.error = std::abs(q7 - q5);
    return out;
  }

  // The degree-5 rule alone (for the exactness tests): Q₅ over the region.
  double embedded_value(std::span<const double> f, double volume) const noexcept {
    double sum2 = 0.0;
    double sum3 = 0.0;
    for (std::size_t k = 0; k < s_; ++k) {
      sum2 += f[1 + 4 * k] + f[2 + 4 * k];
      sum3 += f[3 + 4 * k] + f[4 + 4 * k];
    }
    const double sum4 = pairwise_sum(f.subspan(1 + 4 * s_, 4 * pairs_.size()));
    return volume * (e1_ * f[0] + e2_ * sum2 + e3_ * sum3 + e4_ * sum4);
  }

  // Σ|w_i| over the degree-7 nodes on a box of volume 1: how much the rule amplifies an error in
  // the values (1 for a positive rule; w₁ < 0 makes it larger), for rounding bounds.
  double absolute_weight_sum() const noexcept {
    const double s = static_cast<double>(s_);
    return std::abs(w1_) + 2.0 * s * (std::abs(w2_) + std::abs(w3_)) +
           2.0 * s * (s - 1.0) * std::abs(w4_) + std::ldexp(1.0, static_cast<int>(s_)) * w5_;
  }

 private:
  std::size_t s_;
  double w1_, w2_, w3_, w4_, w5_;
  double e1_, e2_, e3_, e4_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
};

}  // namespace quadmc
