// h-adaptive Genz–Malik cubature as a method (rules/adaptive_cubature.hpp), for s ≥ 2, under two
// controls:
//   budget     (default) N is the most it may spend; it refines, halving its error estimate per
//              round, until the next split would not fit;
//   tolerance  until its error estimate Σ|Q₇ − Q₅| over the regions is at most the cell's
//              absolute tolerance, within the budget (budget.max_evaluations, else 2^30).
// Its error estimate is reported in both. There is no fixed size: an adaptive method chooses its
// own regions, so "fixed" would only be "budget" under another name.
#include "families.hpp"

#include "quadmc/rules/adaptive_cubature.hpp"

#include <fmt/format.h>

#include <array>
#include <memory>

namespace quadmc::methods {
namespace {

class genz_malik_method final : public method {
 public:
  using method::method;

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s < 2) {
      return fmt::format(
          "genz_malik needs s ≥ 2 (the Genz–Malik rule is a cubature rule; in 1D use romberg or "
          "gauss_legendre); the integrand has s = {}",
          f.s);
    }
    if (f.s > genz_malik_max_dimension) {
      return fmt::format("genz_malik needs s ≤ {} (2^s nodes per region); the integrand has s = {}",
                         genz_malik_max_dimension, f.s);
    }
    return std::nullopt;
  }

  // The budget itself: the run decides how much of it to spend.
  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (s < 2 || s > genz_malik_max_dimension) {
      return {std::nullopt,
              fmt::format("genz_malik needs 2 ≤ s ≤ {} (s = {})", genz_malik_max_dimension, s)};
    }
    const std::uint64_t points = genz_malik_rule::points_for(s);
    if (N < points) {
      return {std::nullopt,
              fmt::format("N is below one region's 2^s + 2s² + 2s + 1 = {} evaluations", points)};
    }
    return {cell_size{N, 0, 0, 0}, {}};
  }

  // No algebraic rate is proven for the adaptive subdivision (docs/theory.md#genz-malik): the
  // degree-7 rule on a uniform subdivision would give N^(−8/s) on smooth f, and adaptivity may do
  // better on a peak, but the fitted slope is reported without a theoretical one to judge it.
  theoretical_rate theory(const integrand_class&) const override {
    return {std::nullopt,
            "h-adaptive: no proven algebraic rate (uniform subdivision of a degree-7 rule would "
            "give N^(-8/s) on smooth f)",
            "docs/theory.md#genz-malik; [Genz & Malik 1980]"};
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    adaptive_cubature_options options;
    options.max_evaluations = cell.size.evaluations;
    options.absolute_tolerance = cell.control == cell_control::tolerance ? cell.tolerance : 0.0;
    options.threads = context.threads;
    const adaptive_cubature_result r = genz_malik_cubature(cell.function, options);
    repetition_result out;
    out.value = r.value;
    out.evaluations = r.evaluations;
    out.error_estimate = r.error_estimate;
    return out;
  }
};

constexpr std::array<cell_control, 2> controls{cell_control::budget, cell_control::tolerance};

const std::array<method_descriptor, 1> descriptors{{
    {"genz_malik",
     "h-adaptive cubature, Genz-Malik degree-7 rule with its degree-5 error estimate (s >= 2)",
     method_kind::deterministic,
     {},
     controls,
     [](const method_descriptor& d, option_reader&) -> std::unique_ptr<const method> {
       return std::make_unique<genz_malik_method>(d);
     }},
}};

}  // namespace

std::span<const method_descriptor> adaptive_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
