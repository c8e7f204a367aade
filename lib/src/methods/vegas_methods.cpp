// VEGAS+ as a method (estimators/vegas.hpp), randomized, under two controls:
//   budget     (default) N is the budget, spent in `iterations` equal iterations, the first
//              `training_iterations` only adapting;
//   tolerance  until σ̂ of the combined iterations is at most the cell's absolute tolerance (with
//              at least two combined), within the budget (budget.max_evaluations / repetitions,
//              else 2^30).
// It reports σ̂ as its standard error and error estimate, and the combination's χ²/dof and Q
// (the chi2_per_dof and q_value columns).
#include "families.hpp"

#include "quadmc/estimators/vegas.hpp"

#include <fmt/format.h>

#include <array>
#include <memory>

namespace quadmc::methods {
namespace {

class vegas_method final : public method {
 public:
  vegas_method(const method_descriptor& d, const vegas_options& options)
      : method(d), options_(options) {}

  sizing size_for(std::uint64_t N, std::size_t) const override {
    const std::uint64_t smallest = vegas_min_iteration_evaluations * options_.iterations;
    if (N < smallest) {
      return {std::nullopt,
              fmt::format("N is below {} iterations of {} evaluations = {}", options_.iterations,
                          vegas_min_iteration_evaluations, smallest)};
    }
    return {cell_size{N, 0, 0, 0}, {}};
  }

  // The σ of an adapted density still falls as N^(−1/2) once the grid has converged; while it
  // adapts, and through the adaptive stratification in low s, it falls faster: the σ̂ it reports
  // per cell is the verdict's computed reason then (theoretical_rate::adaptive).
  theoretical_rate theory(const integrand_class& f) const override {
    return adaptive_monte_carlo_rate(
        f,
        "σ/√N with the adapted density's σ; adaptive stratification can be steeper "
        "in low s",
        "docs/theory.md#vegas; [Lepage 1978]; [Lepage 2021]");
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    vegas_options options = options_;
    options.max_evaluations = cell.size.evaluations;
    options.absolute_tolerance = cell.control == cell_control::tolerance ? cell.tolerance : 0.0;
    options.threads = context.threads;
    if (options.absolute_tolerance > 0.0) {
      // The first iterations cannot be larger than the budget.
      options.evaluations_per_iteration =
          std::min(options.evaluations_per_iteration, options.max_evaluations);
    }
    const vegas_result r = vegas(cell.function, options, context.seed, cell.stream, context.rng);
    repetition_result out;
    out.value = r.value;
    out.std_error = r.std_error;
    out.error_estimate = r.std_error;
    out.evaluations = r.evaluations;
    out.chi2_per_dof = r.chi2_per_dof;
    out.q_value = r.q;
    return out;
  }

 private:
  vegas_options options_;
};

constexpr std::array<cell_control, 2> controls{cell_control::budget, cell_control::tolerance};

constexpr std::array<option_doc, 5> option_docs{{
    {"iterations", "budget control: the budget in this many equal iterations, 2…1000 (default 10)"},
    {"training_iterations",
     "iterations that only adapt the grid and strata, not combined, 0…999 and fewer than "
     "iterations (default 3)"},
    {"evaluations_per_iteration",
     "tolerance control: the size of the first iterations, 16…2^40 (default 2000); later ones "
     "grow towards the tolerance, at most 4x per iteration"},
    {"alpha", "grid damping, 0 (frozen grid) … 10 (default 0.5, Lepage 2021)"},
    {"beta", "stratification damping, 0 (uniform strata) … 1 (default 0.75, Lepage 2021)"},
}};

std::unique_ptr<const method> create_vegas(const method_descriptor& d, option_reader& r) {
  vegas_options o;
  if (auto n = r.count("iterations", 2, 1000, "an iteration count between 2 and 1000")) {
    o.iterations = static_cast<unsigned>(*n);
  }
  if (auto n = r.count("training_iterations", 0, 999, "a count between 0 and 999")) {
    o.training_iterations = static_cast<unsigned>(*n);
  }
  if (o.training_iterations >= o.iterations) {
    r.fail(r.has("training_iterations") ? "training_iterations" : "iterations",
           fmt::format("expected training_iterations < iterations (some iterations must be "
                       "combined), got {} and {}",
                       o.training_iterations, o.iterations));
  }
  if (auto n = r.count("evaluations_per_iteration", vegas_min_iteration_evaluations,
                       std::uint64_t{1} << 40, "an evaluation count between 16 and 2^40")) {
    o.evaluations_per_iteration = *n;
  }
  if (auto a = r.number("alpha", "a damping 0 ≤ α ≤ 10")) {
    if (!(*a >= 0.0 && *a <= 10.0)) {
      r.fail("alpha", fmt::format("expected a damping 0 ≤ α ≤ 10, got {}", *a));
    }
    o.alpha = *a;
  }
  if (auto b = r.number("beta", "a damping 0 ≤ β ≤ 1")) {
    if (!(*b >= 0.0 && *b <= 1.0)) {
      r.fail("beta", fmt::format("expected a damping 0 ≤ β ≤ 1, got {}", *b));
    }
    o.beta = *b;
  }
  return std::make_unique<vegas_method>(d, o);
}

const std::array<method_descriptor, 1> descriptors{{
    {"vegas",
     "VEGAS+ (Lepage 2021): adaptive importance grid and adaptive stratification, iterations "
     "combined by inverse variance, chi2/dof and Q reported",
     method_kind::randomized, option_docs, controls, create_vegas},
}};

}  // namespace

std::span<const method_descriptor> vegas_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
