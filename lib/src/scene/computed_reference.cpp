// compute_reference: tanh-sinh in s = 1, Genz–Malik h-adaptive cubature in s ≥ 2
// (computed_reference.hpp; docs/theory.md#references-without-a-closed-form).
#include "quadmc/scene/computed_reference.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/rules/adaptive_cubature.hpp"
#include "quadmc/rules/weighted_sum.hpp"

#include <fmt/format.h>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace quadmc {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// tanh-sinh stops once two levels differ by at most τ·∫|f|; on an analytic f (or one with power
// or log singularities at the ends) each level doubles the correct digits, so the estimate,
// which is the previous level's error, overstates the returned value's by far
// ([Takahasi & Mori 1974]). Its own floor is ≈ 1e-13·∫|f| (the rounding of the abscissas: Boost
// 1.74 states 7.3e-14 for ∫1 over [0.3, 1]), so τ = 1e-12 is the tightest target always reached.
constexpr double tanh_sinh_tolerance = 1e-12;
// Genz–Malik: the degree-7 rule converges as h^8 per region, so 1e-12 of the magnitude costs
// about 10^5 to 10^7 evaluations in s ≤ 3 on a smooth f; the budget bounds a slow case (an
// integrand with unbounded derivatives at a face) to a few seconds of planning.
constexpr double cubature_tolerance = 1e-12;
constexpr std::uint64_t cubature_budget = std::uint64_t{1} << 24;
// More pieces than this and the box is integrated whole (the estimate then misjudges the kinks).
constexpr std::size_t max_pieces = 1024;

// Per axis, the edges of the pieces on which f is smooth: the domain's ends and the kinks and
// jumps f declares inside (integrand_info::endpoint_derivatives, separable_factors). Both error
// estimates assume f smooth between the nodes: across a kink Genz–Malik's |Q₇ − Q₅| is below the
// true error by orders of magnitude (genz_continuous: 1e-12 stated, 3e-9 true), so the rules
// integrate each piece separately.
std::vector<std::vector<double>> piece_edges(const integrand_info& info) {
  const std::size_t s = info.dimension();
  std::vector<std::vector<double>> edges(s);
  for (std::size_t j = 0; j < s; ++j) {
    const double lo = info.domain.lower[j];
    const double hi = info.domain.upper[j];
    std::vector<double> inner;
    if (info.endpoint_derivatives && info.endpoint_derivatives->factors.size() == s) {
      for (const derivative_jump& k : info.endpoint_derivatives->factors[j].kinks) {
        inner.push_back(k.location);
      }
    }
    if (info.separable_factors.size() == s) {
      for (const jump_discontinuity& d : info.separable_factors[j].jumps) {
        inner.push_back(d.location);
      }
    }
    std::sort(inner.begin(), inner.end());
    edges[j].push_back(lo);
    for (const double x : inner) {
      if (x > edges[j].back() && x < hi) edges[j].push_back(x);
    }
    edges[j].push_back(hi);
  }
  return edges;
}

// The pieces' boxes: the product of the axes' intervals, or the whole box when there would be
// more than max_pieces.
std::vector<box> pieces_of(const integrand_info& info) {
  const std::vector<std::vector<double>> edges = piece_edges(info);
  std::size_t count = 1;
  for (const auto& e : edges) {
    count *= e.size() - 1;
    if (count > max_pieces) return {info.domain};
  }
  std::vector<box> out;
  std::vector<std::size_t> index(edges.size(), 0);
  for (std::size_t p = 0; p < count; ++p) {
    box b;
    for (std::size_t j = 0; j < edges.size(); ++j) {
      b.lower.push_back(edges[j][index[j]]);
      b.upper.push_back(edges[j][index[j] + 1]);
    }
    out.push_back(std::move(b));
    for (std::size_t j = 0; j < edges.size(); ++j) {
      if (++index[j] < edges[j].size() - 1) break;
      index[j] = 0;
    }
  }
  return out;
}

// f restricted to one piece: the same values, the piece as its domain.
class on_piece {
 public:
  on_piece(const any_integrand& f, box piece) : f_(&f), info_(f.info()) {
    info_.domain = std::move(piece);
  }
  std::size_t dimension() const noexcept { return info_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const { f_->evaluate(x, y); }
  const integrand_info& info() const noexcept { return info_; }

 private:
  const any_integrand* f_;
  integrand_info info_;
};

computed_reference tanh_sinh_reference(const any_integrand& f) {
  require_integration_box(f.info().domain);
  std::uint64_t evaluations = 0;
  auto value_at = [&](double x) {
    double y = 0.0;
    f.evaluate(std::span<const double>(&x, 1), std::span<double>(&y, 1));
    ++evaluations;
    return y;
  };
  boost::math::quadrature::tanh_sinh<double> integrator;  // Boost 1.74: integrate is not const
  computed_reference out;
  out.method = "tanh-sinh (Boost.Math)";
  out.relative_tolerance = tanh_sinh_tolerance;
  out.converged = true;
  neumaier_sum value;
  double error_sum = 0.0;
  double l1_sum = 0.0;
  for (const box& piece : pieces_of(f.info())) {
    double error = 0.0;
    double l1 = 0.0;
    value.add(integrator.integrate(value_at, piece.lower[0], piece.upper[0], tanh_sinh_tolerance,
                                   &error, &l1));
    out.converged = out.converged && error <= tanh_sinh_tolerance * l1;
    error_sum += error;
    l1_sum += l1;
  }
  out.value = value.value();
  out.evaluations = evaluations;
  out.uncertainty = error_sum + 4.0 * eps * l1_sum;
  return out;
}

computed_reference cubature_reference(const any_integrand& f) {
  const integrand_info& info = f.info();
  require_integration_box(info.domain);
  const std::uint64_t points = genz_malik_rule(f.dimension()).points();
  // The magnitude the tolerance is relative to: max|f|·V where the family knows max|f|, else a
  // first estimate's |I| (a small run, 64 regions' worth).
  adaptive_cubature_options first;
  first.max_evaluations = 64 * points;
  const adaptive_cubature_result rough = genz_malik_cubature(f, first);
  double scale = std::abs(rough.value);
  if (const auto& peak = info.derivative_bound[0]) {
    scale = std::max(scale, *peak * info.domain.volume());
  }
  computed_reference out;
  out.method = "Genz–Malik h-adaptive cubature";
  out.relative_tolerance = cubature_tolerance;
  out.evaluations = rough.evaluations;
  if (!(scale > 0.0)) {  // f = 0 at every node of the rough run: nothing tighter to ask for
    out.value = rough.value;
    out.converged = rough.converged;
    out.uncertainty = rough.error_estimate;
    return out;
  }
  const std::vector<box> pieces = pieces_of(info);
  const auto count = static_cast<double>(pieces.size());
  out.converged = true;
  neumaier_sum value;
  double error_sum = 0.0;
  for (const box& piece : pieces) {
    adaptive_cubature_options options;
    options.max_evaluations = std::max(points, cubature_budget / pieces.size());
    options.absolute_tolerance = cubature_tolerance * scale / count;
    const adaptive_cubature_result r = genz_malik_cubature(on_piece(f, piece), options);
    value.add(r.value);
    error_sum += r.error_estimate;
    out.evaluations += r.evaluations;
    out.converged = out.converged && r.converged;
  }
  out.value = value.value();
  out.uncertainty = error_sum + 4.0 * eps * scale;
  return out;
}

}  // namespace

std::string computed_reference::describe() const {
  return fmt::format("{}, relative tolerance {:g}, {} evaluations, uncertainty {:.2g}{}", method,
                     relative_tolerance, evaluations, uncertainty,
                     converged ? "" : " (tolerance not reached within the budget)");
}

computed_reference compute_reference(const any_integrand& f) {
  const std::size_t s = f.dimension();
  require(s >= 1 && s <= max_computed_reference_dimension, "s", s,
          fmt::format("a dimension from 1 to {} for a computed reference",
                      max_computed_reference_dimension));
  return s == 1 ? tanh_sinh_reference(f) : cubature_reference(f);
}

}  // namespace quadmc
