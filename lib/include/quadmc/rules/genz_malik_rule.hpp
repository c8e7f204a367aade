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
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>

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

  // Nothing is tabulated: the weights are nine numbers, and nodes() decodes the pair of a pair
  // node from its index once per call, so a rule costs a few flops to build and allocates
  // nothing (a run to 10⁻³ in s = 2 builds one per call and takes microseconds).
  explicit genz_malik_rule(std::size_t s) : s_(s) {
    require(s >= 2 && s <= genz_malik_max_dimension, "Genz–Malik dimension s", s,
            "between 2 and 40 (the rule is built for s ≥ 2; 2^s nodes per region)");
    const double d = static_cast<double>(s);
    w1_ = (12824.0 - 9120.0 * d + 400.0 * d * d) / 19683.0;
    w2_ = 980.0 / 6561.0;
    w3_ = (1820.0 - 400.0 * d) / 19683.0;
    w4_ = 200.0 / 19683.0;
    // 2^s is exact in a double for s ≤ 40 (the same value std::ldexp(1.0, s) gives, without the
    // call into libm).
    w5_ = 6859.0 / 19683.0 / static_cast<double>(std::uint64_t{1} << s);
    e1_ = (729.0 - 950.0 * d + 50.0 * d * d) / 729.0;
    e2_ = 245.0 / 486.0;
    e3_ = (265.0 - 100.0 * d) / 1458.0;
    e4_ = 25.0 / 729.0;
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
    if (k < 4 * pair_count()) {
      const auto [i, j] = pair(static_cast<std::size_t>(k / 4));
      const unsigned signs = static_cast<unsigned>(k % 4);
      x[i] = centre[i] + ((signs & 1u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[i];
      x[j] = centre[j] + ((signs & 2u) != 0 ? 1.0 : -1.0) * lambda4 * half_width[j];
      return;
    }
    k -= 4 * pair_count();
    for (std::size_t j = 0; j < s_; ++j) {
      const double sign = ((k >> j) & 1u) != 0 ? -1.0 : 1.0;
      x[j] = centre[j] + sign * lambda5 * half_width[j];
    }
  }

  // Nodes first, first + 1, … of one region into out (count rows of s, row-major): the same
  // doubles as node() for each index, written in bulk. Every row but a vertex is the centre with
  // one or two coordinates moved, so those rows are the centre row repeated, then set four rows
  // (one axis or pair of axes) at a time. The vertices (most of a region's rows once s ≳ 6) are
  // built by blocks [v, v + 2^m) aligned to 2^m: row v written, then rows [v, v + 2^t) copied to
  // [v + 2^t, v + 2^(t+1)) with coordinate t set to c_t − λ₅h_t, for t < m, so a row costs a
  // share of one memcpy of many rows and one store. For s ≤ 4 a row is at most four doubles, and
  // writing each row directly (the dimension a template argument, so no loop over coordinates
  // and no memcpy call) is cheaper than copying. Callgrind, the rule's part of a run to 10⁻⁶ on
  // the Genz Gaussian (these nodes, the batch layout, Q₇, Q₅ and the split axis) per node, before
  // (one row at a time, a copy of the previous row) → now: s = 2: 61 → 35 instructions, s = 4:
  // 54 → 28, s = 8: 67 → 22 (hcubature's: 48, 40 and 38, one memcpy per row).
  void nodes(std::uint64_t first, std::size_t count, std::span<const double> centre,
             std::span<const double> half_width, double* out) const noexcept {
    switch (s_) {
      case 2:
        return write_nodes<2>(first, count, centre.data(), half_width.data(), out);
      case 3:
        return write_nodes<3>(first, count, centre.data(), half_width.data(), out);
      case 4:
        return write_nodes<4>(first, count, centre.data(), half_width.data(), out);
      default:
        return write_nodes<0>(first, count, centre.data(), half_width.data(), out);
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
    const std::size_t vertex_first = pair_first + 4 * pair_count();
    const double sum4 = pairwise_sum(f.subspan(pair_first, 4 * pair_count()));
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
    const double sum4 = pairwise_sum(f.subspan(1 + 4 * s_, 4 * pair_count()));
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
  // Pair p of the s(s−1)/2 pairs (a < b) in order (0,1), (0,2), …, (0,s−1), (1,2), …: O(s).
  std::pair<std::size_t, std::size_t> pair(std::size_t p) const noexcept {
    std::size_t a = 0;
    while (p >= s_ - 1 - a) {
      p -= s_ - 1 - a;
      ++a;
    }
    return {a, a + 1 + p};
  }
  std::size_t pair_count() const noexcept { return s_ * (s_ - 1) / 2; }

  // nodes() for s = S, or for any s (s_) when S = 0.
  template <std::size_t S>
  void write_nodes(std::uint64_t first, std::size_t count, const double* centre,
                   const double* half_width, double* x) const noexcept {
    const std::size_t s = S != 0 ? S : s_;
    const std::uint64_t pair_first = 1 + 4 * s;
    const std::uint64_t vertex_first = pair_first + 4 * pair_count();
    const std::uint64_t end = first + count;
    const std::uint64_t centred_end = std::min(end, vertex_first);
    std::uint64_t index = first;
    if (index < centred_end) {
      repeat_row<S>(centre, static_cast<std::size_t>(centred_end - index), x);
      if (index == 0) {
        ++index;
        x += s;
      }
      // Axis k: nodes 1 + 4k + {0, 1, 2, 3} = c_k − λ₂h_k, c_k + λ₂h_k, c_k − λ₃h_k, c_k + λ₃h_k
      // (c + (−λ)·h as node() computes it is exactly c − λ·h).
      const std::uint64_t axis_end = std::min(centred_end, pair_first);
      while (index < axis_end) {
        const auto axis = static_cast<std::size_t>((index - 1) / 4);
        const double c = centre[axis];
        const double step2 = lambda2 * half_width[axis];
        const double step3 = lambda3 * half_width[axis];
        const auto from = static_cast<unsigned>((index - 1) % 4);
        const auto to = static_cast<unsigned>(std::min<std::uint64_t>(4, from + axis_end - index));
        if (from == 0 && to == 4) {
          x[axis] = c - step2;
          x[s + axis] = c + step2;
          x[2 * s + axis] = c - step3;
          x[3 * s + axis] = c + step3;
          x += 4 * s;
        } else {
          const double moved[4] = {c - step2, c + step2, c - step3, c + step3};
          for (unsigned w = from; w < to; ++w, x += s) x[axis] = moved[w];
        }
        index += to - from;
      }
      // Pair (a, b), a < b, in order: 4 nodes with (c_a ∓ λ₄h_a, c_b ∓ λ₄h_b), signs −−, +−, −+,
      // ++.
      if (index < centred_end) {
        auto [a, b] = pair(static_cast<std::size_t>((index - pair_first) / 4));
        while (index < centred_end) {
          const double step_a = lambda4 * half_width[a];
          const double step_b = lambda4 * half_width[b];
          const double xa[2] = {centre[a] - step_a, centre[a] + step_a};
          const double xb[2] = {centre[b] - step_b, centre[b] + step_b};
          const auto from = static_cast<unsigned>((index - pair_first) % 4);
          const auto to =
              static_cast<unsigned>(std::min<std::uint64_t>(4, from + centred_end - index));
          if (from == 0 && to == 4) {
            x[a] = xa[0];
            x[b] = xb[0];
            x[s + a] = xa[1];
            x[s + b] = xb[0];
            x[2 * s + a] = xa[0];
            x[2 * s + b] = xb[1];
            x[3 * s + a] = xa[1];
            x[3 * s + b] = xb[1];
            x += 4 * s;
          } else {
            for (unsigned w = from; w < to; ++w, x += s) {
              x[a] = xa[w & 1u];
              x[b] = xb[w >> 1];
            }
          }
          index += to - from;
          if (++b == s) {
            ++a;
            b = a + 1;
          }
        }
      }
    }
    if (end <= vertex_first) return;
    // Vertex v: coordinate j is c_j − λ₅h_j where bit j of v is set, else c_j + λ₅h_j.
    double plus[genz_malik_max_dimension];
    double minus[genz_malik_max_dimension];
    for (std::size_t j = 0; j < s; ++j) {
      plus[j] = centre[j] + lambda5 * half_width[j];
      minus[j] = centre[j] - lambda5 * half_width[j];
    }
    std::uint64_t v = std::max(first, vertex_first) - vertex_first;
    const std::uint64_t v_end = end - vertex_first;
    if constexpr (S != 0) {
      for (; v < v_end; ++v, x += S) {
        for (std::size_t j = 0; j < S; ++j) x[j] = ((v >> j) & 1u) != 0 ? minus[j] : plus[j];
      }
    } else {
      while (v < v_end) {
        // The largest block [v, v + 2^m) that is aligned to 2^m and inside the run.
        const int aligned = v == 0 ? 64 : std::countr_zero(v);
        const int m = std::min(aligned, static_cast<int>(std::bit_width(v_end - v)) - 1);
        for (std::size_t j = 0; j < s; ++j) x[j] = ((v >> j) & 1u) != 0 ? minus[j] : plus[j];
        for (int t = 0; t < m; ++t) {
          const std::size_t rows = std::size_t{1} << t;
          double* copy = x + rows * s;
          std::memcpy(copy, x, rows * s * sizeof(double));
          const auto axis = static_cast<std::size_t>(t);
          for (std::size_t r = 0; r < rows; ++r) copy[r * s + axis] = minus[axis];
        }
        x += (std::size_t{1} << m) * s;
        v += std::uint64_t{1} << m;
      }
    }
  }

  // rows copies of the row `from` into x. For a fixed S, row by row (S doubles); otherwise the
  // first row copied, then rows [0, n) copied to [n, 2n) by memcpy: log₂(rows) calls, not rows.
  template <std::size_t S>
  void repeat_row(const double* from, std::size_t rows, double* x) const noexcept {
    if constexpr (S != 0) {
      double row[S];
      std::copy_n(from, S, row);
      for (std::size_t r = 0; r < rows; ++r, x += S) std::copy_n(row, S, x);
    } else {
      const std::size_t s = s_;
      std::copy_n(from, s, x);
      for (std::size_t done = 1; done < rows;) {
        const std::size_t n = std::min(done, rows - done);
        std::memcpy(x + done * s, x, n * s * sizeof(double));
        done += n;
      }
    }
  }

  std::size_t s_;
  double w1_, w2_, w3_, w4_, w5_;
  double e1_, e2_, e3_, e4_;
};

}  // namespace quadmc
