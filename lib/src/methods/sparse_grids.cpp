// The sparse grids as methods: `smolyak`, the isotropic Smolyak grid of a nested rule
// (rules/smolyak_grid.hpp, a weighted point set summed by rules/weighted_sum.hpp), and
// `adaptive_sparse_grid`, the dimension-adaptive grid of [Gerstner & Griebel 2003]
// (rules/dimension_adaptive_sparse_grid.hpp) under budget or tolerance control.
//
// smolyak: a scene's N maps to the largest level L whose distinct-node count N(L, s) ≤ N, counted
// exactly (smolyak_point_count); the plan prints L ("L=3" in the n/axis column), and a larger N
// that gives the same level is a "same grid" skip. Levels stop at the 1D tables' end
// (nested_rule.hpp: 14 for Clenshaw–Curtis). Every run reports Σ|w| of its grid, tallied while
// the kernel sums, so the analysis scales the rounding floor by it (analysis/rounding_floor.hpp).
//
// adaptive_sparse_grid: "budget" (default) spends at most N evaluations, stopping earlier once its
// estimate η is below 4ε·|Q| (nothing left to resolve in double); "tolerance" runs until η is at
// most the cell's tolerance, within the budget. N is capped at 2^22 (every value is kept).
#include "families.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/rules/dimension_adaptive_sparse_grid.hpp"
#include "quadmc/rules/smolyak_grid.hpp"
#include "quadmc/rules/weighted_sum.hpp"

#include <fmt/format.h>

#include <array>
#include <memory>
#include <utility>

namespace quadmc::methods {
namespace {

constexpr std::array<std::string_view, 3> rule_names{"clenshaw_curtis", "gauss_patterson",
                                                     "trapezoid"};

// The `rule` option; Clenshaw–Curtis when absent. `given` marks a rule other than the default,
// which then joins the label (smolyak_gauss_patterson), so the default label stays "smolyak"
// whether or not the table names clenshaw_curtis.
struct rule_option {
  nested_rule_kind kind = nested_rule_kind::clenshaw_curtis;
  bool other_than_default = false;
};

rule_option read_rule(option_reader& r, std::span<const std::string_view> allowed) {
  rule_option o;
  if (auto name = r.choice("rule", allowed)) {
    o.kind = *parse_nested_rule_kind(*name);
    o.other_than_default = o.kind != nested_rule_kind::clenshaw_curtis;
  }
  return o;
}

class smolyak_method final : public method {
 public:
  smolyak_method(const method_descriptor& d, rule_option rule) : method(d), rule_(rule) {}

  std::string label_suffix() const override {
    return rule_.other_than_default ? fmt::format("_{}", to_string(rule_.kind)) : std::string();
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    const nested_rule& rule = nested_rule_table(rule_.kind);
    std::optional<cell_size> best;
    for (unsigned L = 0; L <= rule.max_level(); ++L) {
      const auto n = smolyak_point_count(rule, s, L);
      if (!n || *n > N) break;  // counts grow with L
      best = cell_size{*n, 0, 0, 0, static_cast<int>(L)};
    }
    if (!best) return {std::nullopt, "N is below the smallest grid, 1 evaluation"};
    // The tables end at max_level: a larger N gets the same grid, and the plan says why.
    if (static_cast<unsigned>(best->level) == rule.max_level()) {
      return {best, fmt::format("level {} is the last of the {} tables", rule.max_level(),
                                to_string(rule_.kind))};
    }
    return {best, {}};
  }

  theoretical_rate theory(const integrand_class& f) const override {
    theoretical_rate rate = sparse_grid_rate(f);
    if (rule_.kind == nested_rule_kind::trapezoid && f.regularity == smoothness::analytic) {
      rate.note += "; the periodic trapezoid rule assumes f periodic in every coordinate";
    }
    return rate;
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const std::size_t s = cell.function.dimension();
    const auto level = static_cast<unsigned>(cell.size.level);
    const smolyak_grid grid(nested_rule_table(rule_.kind), s, level);
    const chunking layout{grid.size(), rule_chunk_points};
    std::vector<neumaier_sum> tally(layout.chunks());
    const rule_result r = weighted_sum(cell.function, tallied_grid{&grid, &tally}, context.threads);
    neumaier_sum abs_weights;
    for (const neumaier_sum& chunk : tally) abs_weights.merge(chunk);
    repetition_result out;
    out.value = r.value;
    out.evaluations = r.evaluations;
    out.absolute_weight_sum = abs_weights.value();
    return out;
  }

  // The Σ|w| tally is written on the side of the sum, so the sum's chunks stay on each process.
  bool shares_chunks() const override {
    return weighted_sum_shares_chunks<tallied_grid>(summation::pairwise);
  }

 private:
  // The grid as the kernel sees it, adding Σ|w| on the way: each batch's |w| go to the Neumaier
  // sum of its chunk (the kernel's unit of parallel work, core/batching.hpp: one thread runs a
  // chunk's batches in order), and the chunks are folded in order after the sum, so Σ|w| is the
  // same on any thread count and costs a pass over 256 weights per batch, not a second pass over
  // the grid.
  struct tallied_grid {
    // The tally is written on the side of the sum (rules/weighted_sum.hpp, writes_on_the_side).
    // [[maybe_unused]]: read only by that concept, which clang 14 does not count as a use.
    [[maybe_unused]] static constexpr bool writes_on_the_side = true;
    const smolyak_grid* grid;
    std::vector<neumaier_sum>* tally;

    std::uint64_t size() const noexcept { return grid->size(); }
    std::size_t dimension() const noexcept { return grid->dimension(); }
    void add(std::uint64_t first, std::span<const double> weights) const noexcept {
      neumaier_sum& chunk = (*tally)[static_cast<std::size_t>(first / rule_chunk_points)];
      for (const double w : weights) chunk.add(std::abs(w));
    }
    void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
      grid->generate(first, nodes, weights);
      add(first, weights);
    }
    struct on_box {
      [[maybe_unused]] static constexpr bool writes_on_the_side = true;
      smolyak_grid::on_box points;
      const tallied_grid* owner;
      void generate(std::uint64_t first, std::span<double> x, std::span<double> weights) const {
        points.generate(first, x, weights);
        owner->add(first, weights);
      }
    };
    on_box mapped(const cube_to_box& map) const { return on_box{grid->mapped(map), this}; }
  };

  rule_option rule_;
};

class adaptive_sparse_grid_method final : public method {
 public:
  adaptive_sparse_grid_method(const method_descriptor& d, rule_option rule)
      : method(d), rule_(rule) {}

  std::string label_suffix() const override {
    return rule_.other_than_default ? fmt::format("_{}", to_string(rule_.kind)) : std::string();
  }

  sizing size_for(std::uint64_t N, std::size_t) const override {
    // The process's 1D tables (nested_rule_table: 0.18 s for Clenshaw–Curtis's 14 levels) are
    // built here, when the scene is planned, so that the first cell's timed run does not pay
    // for them (docs/design.md#stable-timing); the smolyak method's size_for reads them too.
    static_cast<void>(nested_rule_table(rule_.kind));
    if (N > adaptive_sparse_grid_max_evaluations) {
      return {std::nullopt,
              fmt::format("N above the adaptive grid's cap of 2^22 = {} evaluations (it keeps "
                          "every value)",
                          adaptive_sparse_grid_max_evaluations)};
    }
    return {cell_size{N, 0, 0, 0}, {}};
  }

  theoretical_rate theory(const integrand_class& f) const override { return sparse_grid_rate(f); }

  repetition_result run(const method_cell& cell, const run_context&) const override {
    adaptive_sparse_grid_options options;
    options.max_evaluations =
        std::min<std::uint64_t>(cell.size.evaluations, adaptive_sparse_grid_max_evaluations);
    if (cell.control == cell_control::tolerance) {
      options.absolute_tolerance = cell.tolerance;
    } else {
      // 4ε·|Q|: the sum's own rounding; refining below it resolves nothing in double.
      options.relative_tolerance = 4.0 * std::numeric_limits<double>::epsilon();
    }
    const adaptive_sparse_grid_result r =
        dimension_adaptive_sparse_grid(cell.function, nested_rule_table(rule_.kind), options);
    repetition_result out;
    out.value = r.value;
    out.evaluations = r.evaluations;
    out.error_estimate = r.error_estimate;
    out.absolute_weight_sum = r.absolute_weight_sum;
    return out;
  }

 private:
  rule_option rule_;
};

constexpr std::array<option_doc, 1> smolyak_options{{
    {"rule",
     "the nested 1D rule: \"clenshaw_curtis\" (default; 1, 3, 5, 9, … nodes, levels 0 to 14), "
     "\"gauss_patterson\" (1, 3, 7, 15, … nodes, interior only, levels 0 to 7: the tables end at "
     "255 nodes), \"trapezoid\" (1, 2, 4, … nodes, levels 0 to 16, for integrands periodic in "
     "every coordinate); N beyond the last level's grid gives that grid again (the plan says "
     "so); the label gets the suffix unless clenshaw_curtis"},
}};
constexpr std::array<option_doc, 1> adaptive_options{{
    {"rule",
     "the nested 1D rule: \"clenshaw_curtis\" (default) or \"gauss_patterson\"; the label gets "
     "the suffix unless clenshaw_curtis"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};
constexpr std::array<cell_control, 2> budget_or_tolerance{cell_control::budget,
                                                          cell_control::tolerance};

const std::array<method_descriptor, 2> descriptors{{
    {"smolyak",
     "isotropic Smolyak sparse grid on a nested rule, N = distinct nodes of the largest level "
     "that fits",
     method_kind::deterministic, smolyak_options, fixed_only,
     [](const method_descriptor& d, option_reader& r) -> std::unique_ptr<const method> {
       return std::make_unique<smolyak_method>(d, read_rule(r, rule_names));
     }},
    {"adaptive_sparse_grid",
     "dimension-adaptive sparse grid (Gerstner-Griebel) on Clenshaw-Curtis or Gauss-Patterson, "
     "with its own error estimate",
     method_kind::deterministic, adaptive_options, budget_or_tolerance,
     [](const method_descriptor& d, option_reader& r) -> std::unique_ptr<const method> {
       constexpr std::array<std::string_view, 2> allowed{"clenshaw_curtis", "gauss_patterson"};
       return std::make_unique<adaptive_sparse_grid_method>(d, read_rule(r, allowed));
     }},
}};

}  // namespace

std::span<const method_descriptor> sparse_grid_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
