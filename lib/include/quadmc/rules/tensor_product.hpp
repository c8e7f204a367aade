// Tensor-product quadrature over a box: the one kernel behind every rule of this layer, 1D
// included.
//
// Q(f) = Π(b_j − a_j) · Σ_{k_1…k_s} w_{k_1}⋯w_{k_s} f(a_1 + (b_1 − a_1)t_{k_1}, …), the product of
// a 1D rule with m nodes along each of the s axes, N = m^s evaluations
// (docs/theory.md#tensor-products; [Ramamoorthi 2009, §1.2]). Use it for smooth integrands in a few
// dimensions; its error is O(N^(−r/s)) for a rule of order r, so past s ≈ 4 Monte Carlo and QMC win
// (the curse of dimensionality, docs/theory.md#tensor-products), and a jump across a non-axis
// surface gives only O(N^(−1/s)) (docs/theory.md#jumps).
//
// How it runs (docs/design.md#hot-path-contract):
//  - the grid is never stored: a chunk decodes its first flat index into a multi-index (last
//    axis fastest) and walks on like an odometer, recomputing a node only when its axis moves;
//  - points go to the integrand in batches of 256 (row-major x[i*s + j]); each batch's terms
//    w_i·f_i are summed pairwise and batches are added with Neumaier's compensated sum, so the
//    rounding error stays O(ε·Σ|w f|) for any N (summation.hpp);
//  - chunks of 2^14 points are the unit of parallel work; their boundaries depend only on N, and
//    parallel_reduce folds them in chunk order, so any thread count gives the same bits;
//  - the sum can instead be naive, all-Neumaier or long double (enum summation), so the stress
//    scene can show what each accumulator's rounding floor is on the same terms.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/rule.hpp"
#include "quadmc/rules/rule_result.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace quadmc {

// Points handed to the integrand per call (the project-wide batch, ≥ 256 per virtual call).
inline constexpr std::size_t rule_batch_size = 256;
// Points per parallel chunk: 64 batches, large enough that thread start-up (tens of µs) is paid
// back even for a cheap integrand, small enough that 2 cores stay busy on a 100×100×100 grid.
inline constexpr std::uint64_t tensor_chunk_points = std::uint64_t{1} << 14;

// m^s, the number of points of an s-dimensional tensor grid with m nodes per axis. Throws
// invalid_argument if it is not representable in 64 bits: checked before each multiplication
// (p > (2^64 − 1)/m ⇔ p·m ≥ 2^64), so the test is exact, not a floating-point estimate.
inline std::uint64_t tensor_grid_size(std::uint64_t nodes_per_axis, std::size_t s) {
  require(s >= 1, "dimension s", s, "at least 1");
  require(nodes_per_axis >= 1, "nodes per axis", nodes_per_axis, "at least 1");
  constexpr std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t points = 1;
  for (std::size_t j = 0; j < s; ++j) {
    if (points > limit / nodes_per_axis) {
      throw invalid_argument(
          "nodes per axis", quote(nodes_per_axis),
          fmt::format("nodes^s ≤ 2^64 − 1 for s = {}: the grid has too many points to count in "
                      "64 bits (use fewer panels or a Monte Carlo method)",
                      s));
    }
    points *= nodes_per_axis;
  }
  return points;
}

// Checks a box for a tensor rule: finite bounds, lower ≤ upper (a reversed axis is rejected, not
// read as a sign flip), finite widths.
inline void require_integration_box(const box& domain) {
  require(domain.upper.size() == domain.lower.size(), "domain.upper size", domain.upper.size(),
          fmt::format("the size of domain.lower, {}", domain.lower.size()));
  for (std::size_t j = 0; j < domain.lower.size(); ++j) {
    const double a = domain.lower[j];
    const double b = domain.upper[j];
    require_finite(a, fmt::format("domain.lower[{}]", j));
    require_finite(b, fmt::format("domain.upper[{}]", j));
    require(a <= b, fmt::format("domain.upper[{}]", j), b,
            fmt::format("≥ domain.lower[{}] = {} (a reversed interval is not integrated with a "
                        "minus sign; swap the bounds)",
                        j, quote(a)));
    require(std::isfinite(b - a), fmt::format("domain width upper[{0}] − lower[{0}]", j), b - a,
            "a finite number (the bounds are too far apart for double)");
  }
}

namespace detail {

// The accumulators of enum summation (core/summation.hpp), each a value type with the same three
// operations, so the kernel below is one template and the default path compiles to the same code
// as before the option existed.
struct pairwise_accumulator {
  neumaier_sum sum;
  void add_batch(std::span<const double> terms) noexcept { sum.add(pairwise_sum(terms)); }
  void merge(const pairwise_accumulator& other) noexcept { sum.merge(other.sum); }
  double value() const noexcept { return sum.value(); }
};

struct neumaier_accumulator {
  neumaier_sum sum;
  void add_batch(std::span<const double> terms) noexcept {
    for (double t : terms) sum.add(t);
  }
  void merge(const neumaier_accumulator& other) noexcept { sum.merge(other.sum); }
  double value() const noexcept { return sum.value(); }
};

struct long_double_accumulator {
  long double sum = 0.0L;
  void add_batch(std::span<const double> terms) noexcept {
    for (double t : terms) sum += static_cast<long double>(t);
  }
  void merge(const long_double_accumulator& other) noexcept { sum += other.sum; }
  double value() const noexcept { return static_cast<double>(sum); }
};

// One double carried through every term in index order: the kernel runs its chunks serially and
// hands each chunk the running sum, so this is exactly Σ left to right, never re-associated.
struct naive_accumulator {
  double sum = 0.0;
  void add_batch(std::span<const double> terms) noexcept {
    for (double t : terms) sum += t;
  }
  double value() const noexcept { return sum; }
};

}  // namespace detail

// ∫ f over f.info().domain by the tensor product of `rule` with n panels per axis. 1D is s = 1.
// threads = 0 uses every core; the result is bitwise the same for every thread count.
// `accumulate` chooses how the N terms w·f are summed (core/summation.hpp, enum summation); the
// default is the pairwise/Neumaier scheme described above. summation::naive runs on one thread
// whatever `threads` says (a left-to-right sum cannot be split).
// Throws invalid_argument for bad n, domain or grid size, non_finite_value if f returns NaN/±inf
// (the message names the point). error_estimate is NaN: a fixed rule has no a-posteriori
// estimate (see error_bounds.hpp for a-priori bounds, romberg.hpp for an estimate).
template <integrand F, rule R>
rule_result integrate(const F& f, const R& rule, std::uint64_t n, unsigned threads = 1,
                      summation accumulate = summation::pairwise) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  require(s >= 1, "integrand dimension s", s, "at least 1");
  require(info.domain.dimension() == s, "integrand domain dimension", info.domain.dimension(),
          fmt::format("the integrand's dimension {}", s));
  require_integration_box(info.domain);
  const auto q = rule.nodes(n);
  const std::uint64_t m = q.size();
  const std::uint64_t total = tensor_grid_size(m, s);

  std::vector<double> lower = info.domain.lower;
  std::vector<double> width(s);
  for (std::size_t j = 0; j < s; ++j) width[j] = info.domain.upper[j] - info.domain.lower[j];

  const std::size_t chunks =
      static_cast<std::size_t>(total / tensor_chunk_points + (total % tensor_chunk_points != 0));

  // Nodes and weights come from a table built once per call when an axis has at most
  // tensor_chunk_points of them (each entry is then reused by m^(s−1) points; the rules' node()
  // and weight() divide), else they are computed per point; the same functions either way, so
  // the same bits. The last axis moves fastest; its coordinates are tabulated too.
  const std::size_t last = s - 1;
  const bool tabulated = m <= tensor_chunk_points;
  const std::size_t table_size = tabulated ? static_cast<std::size_t>(m) : 0;
  std::vector<double> node_table(table_size), weight_table(table_size);
  std::vector<double> last_coordinate(table_size);
  for (std::size_t k = 0; k < table_size; ++k) {
    node_table[k] = q.node(k);
    weight_table[k] = q.weight(k);
    last_coordinate[k] = lower[last] + width[last] * node_table[k];
  }
  auto node = [&](std::uint64_t k) { return tabulated ? node_table[k] : q.node(k); };
  auto weight = [&](std::uint64_t k) { return tabulated ? weight_table[k] : q.weight(k); };

  // Adds the terms of chunk c to `sum` (a fresh accumulator, or the running one for naive).
  auto chunk_sum = [&](std::size_t c, auto sum) {
    const std::uint64_t begin = static_cast<std::uint64_t>(c) * tensor_chunk_points;
    const std::uint64_t end = std::min(begin + tensor_chunk_points, total);
    // Buffers once per chunk (2^14 points), never per point.
    std::vector<double> x(rule_batch_size * s);
    std::vector<double> y(rule_batch_size);
    std::vector<double> terms(rule_batch_size);
    std::vector<std::uint64_t> index(s);
    std::vector<double> coordinate(s);
    std::vector<double> axis_weight(s);
    auto place = [&](std::size_t j) {
      coordinate[j] = lower[j] + width[j] * node(index[j]);
      axis_weight[j] = weight(index[j]);
    };
    std::uint64_t rest = begin;
    for (std::size_t j = s; j-- > 0;) {
      index[j] = rest % m;
      rest /= m;
      place(j);
    }
    // The product weight is formed left to right, Π_{j<s−1} w_j first and the last axis's weight
    // last, from the same factors wherever the chunk starts: it does not depend on the chunking.
    auto leading_weight = [&] {
      double w = 1.0;
      for (std::size_t j = 0; j < last; ++j) w *= axis_weight[j];
      return w;
    };
    double w_leading = leading_weight();
    // Locals: a store through x could otherwise alias lower/width and force reloads per point.
    const double last_lower = lower[last], last_width = width[last];
    std::uint64_t k = index[last];  // the last axis's index, kept in a register

    for (std::uint64_t p = begin; p < end;) {
      const std::size_t count =
          static_cast<std::size_t>(std::min<std::uint64_t>(rule_batch_size, end - p));
      for (std::size_t i = 0; i < count; ++i) {
        double* xi = x.data() + i * s;
        for (std::size_t j = 0; j < last; ++j) xi[j] = coordinate[j];
        if (tabulated) {
          xi[last] = last_coordinate[k];
          terms[i] = w_leading * weight_table[k];
        } else {
          xi[last] = last_lower + last_width * q.node(k);
          terms[i] = w_leading * q.weight(k);
        }
        if (++k == m) {  // odometer carry into the leading axes
          k = 0;
          for (std::size_t j = last; j-- > 0;) {
            if (++index[j] < m) {
              place(j);
              break;
            }
            index[j] = 0;
            place(j);
          }
          w_leading = leading_weight();
        }
      }
      const std::span<const double> xs(x.data(), count * s);
      const std::span<double> ys(y.data(), count);
      f.evaluate(xs, ys);
      check_finite_batch(info.name, xs, ys, s);
      for (std::size_t i = 0; i < count; ++i) terms[i] *= y[i];
      sum.add_batch(std::span<const double>(terms.data(), count));
      p += count;
    }
    return sum;
  };

  auto reduce = [&]<class Accumulator>(Accumulator init) {
    return parallel_reduce(
        chunks, threads, init, [&](std::size_t c) { return chunk_sum(c, Accumulator{}); },
        [](Accumulator& acc, const Accumulator& part) { acc.merge(part); });
  };

  double sum = 0.0;
  switch (accumulate) {
    case summation::pairwise:
      sum = reduce(detail::pairwise_accumulator{}).value();
      break;
    case summation::neumaier:
      sum = reduce(detail::neumaier_accumulator{}).value();
      break;
    case summation::long_double:
      sum = reduce(detail::long_double_accumulator{}).value();
      break;
    case summation::naive: {
      detail::naive_accumulator running;
      for (std::size_t c = 0; c < chunks; ++c) running = chunk_sum(c, running);
      sum = running.value();
      break;
    }
  }

  rule_result result;
  result.value = info.domain.volume() * sum;
  result.evaluations = total;
  return result;
}

namespace detail {

// A plain callable double(double) on [a, b] seen as a 1D integrand, so that the convenience form
// below runs the same kernel (one inlined call per point, no type erasure).
template <class G>
class interval_function {
 public:
  interval_function(const G& g, double a, double b) : g_(&g) {
    info_.name = "function";
    info_.domain = box{{a}, {b}};
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = (*g_)(x[i]);
  }
  const integrand_info& info() const noexcept { return info_; }

 private:
  const G* g_;
  integrand_info info_;
};

}  // namespace detail

// ∫_a^b g(x) dx for a plain callable, by the same kernel (the batch integrand path above is the
// one the runner uses; this form is for tests and quick use).
template <class G, rule R>
requires std::is_invocable_r_v<double, const G&, double> rule_result
integrate(const G& g, double a, double b, const R& rule, std::uint64_t n, unsigned threads = 1,
          summation accumulate = summation::pairwise) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b,
          fmt::format("≥ a = {} (swap the bounds for a reversed interval)", quote(a)));
  return integrate(detail::interval_function<G>(g, a, b), rule, n, threads, accumulate);
}

}  // namespace quadmc
