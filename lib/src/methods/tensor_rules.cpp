// The composite rules as methods: rectangles, midpoint, trapezoid, Simpson and Gauss–Legendre,
// each the tensor product of its 1D rule in s dimensions (rules/tensor_product.hpp).
//
// A scene's N maps to the largest grid of p(n)^s ≤ N evaluations, p(n) the rule's nodes per axis
// for n panels (docs/theory.md#conventions): p(n) = n for the rectangles and midpoint, n + 1 for
// the trapezoid and Simpson (the panels share their end nodes; Simpson pairs panels, so n is
// even), m·n for m-point Gauss–Legendre. All of it exact integer arithmetic: pow(4096, 1/3.) =
// 15.999… would floor to the wrong grid. `panels` replaces the ladder with explicit n.
#include "families.hpp"

#include "quadmc/core/integer_powers.hpp"
#include "quadmc/rules/euler_maclaurin.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/jump_error_envelope.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <memory>

namespace quadmc::methods {
namespace {

// Counts above 2^53 are not exactly representable as doubles, which the analysis uses for N.
constexpr std::uint64_t max_panels = std::uint64_t{1} << 53;
constexpr std::size_t max_panel_counts = 256;

// p(n) = per_panel·n + shared for n a multiple of `step`, n ≥ `smallest` (the rule's nodes(n)
// says the same; tests/methods/tensor_rules_test.cpp checks they agree).
struct node_layout {
  std::uint64_t per_panel = 1;
  std::uint64_t shared = 0;
  std::uint64_t step = 1;
  std::uint64_t smallest = 1;

  std::uint64_t points(std::uint64_t n) const noexcept { return per_panel * n + shared; }
  // The largest valid n with points(n) ≤ q, or 0.
  std::uint64_t panels_within(std::uint64_t q) const noexcept {
    if (q < shared) return 0;
    const std::uint64_t n = (q - shared) / per_panel / step * step;
    return n >= smallest ? n : 0;
  }
};

// Options every tensor rule reads.
struct rule_options {
  std::vector<std::uint64_t> panels;  // explicit n per axis; empty = the ladder
  summation accumulator = summation::pairwise;
  bool accumulator_given = false;
};

rule_options read_rule_options(option_reader& r, const node_layout& layout) {
  rule_options o;
  const bool even = layout.step == 2;
  const std::string what =
      even ? fmt::format("an even panel count between {} and 2^53", layout.smallest)
           : std::string("a panel count between 1 and 2^53");
  if (auto panels = r.counts("panels", layout.smallest, max_panels, max_panel_counts, what)) {
    for (std::size_t i = 0; i < panels->size(); ++i) {
      const std::uint64_t n = (*panels)[i];
      // Composite Simpson pairs the panels: an odd n leaves one panel without a partner.
      if (n % layout.step != 0)
        r.fail_element("panels", i, fmt::format("expected {}, got {}", what, n));
      if (i > 0 && n <= (*panels)[i - 1]) {
        r.fail_element(
            "panels", i,
            fmt::format("panel counts must increase, got {} after {}", n, (*panels)[i - 1]));
      }
    }
    o.panels = std::move(*panels);
  }
  constexpr std::array<std::string_view, 4> accumulators{"pairwise", "neumaier", "naive",
                                                         "long_double"};
  if (auto a = r.choice("accumulator", accumulators)) {
    o.accumulator = *parse_summation(*a);
    o.accumulator_given = true;
  }
  return o;
}

// A rule method over any rule of rules/ (rule.hpp): the grid arithmetic, theory and run are the
// same for all; `note` adds what one rule's theory says beside the generic composite rate.
template <class Rule>
class tensor_rule_method final : public method {
 public:
  // Adds what one rule's theory says beside the generic composite rate (order r of the rule).
  using note_fn = void (*)(const integrand_class&, int order, theoretical_rate&);

  tensor_rule_method(const method_descriptor& d, Rule rule, node_layout layout,
                     rule_options options, note_fn note)
      : method(d),
        rule_(std::move(rule)),
        layout_(layout),
        options_(std::move(options)),
        note_(note) {}

  std::string label_suffix() const override {
    // One series per accumulator: midpoint_naive beside midpoint_neumaier.
    return options_.accumulator_given ? fmt::format("_{}", to_string(options_.accumulator))
                                      : std::string();
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    const std::uint64_t q = integer_root(N, s);  // the most points per axis that fit
    const std::uint64_t n = layout_.panels_within(q);
    if (n == 0) {
      const std::uint64_t p = layout_.points(layout_.smallest);
      const auto smallest = checked_power(p, s);
      return {std::nullopt,
              smallest ? fmt::format("N is below the smallest grid, {}^{} = {} evaluations", p, s,
                                     *smallest)
                       : fmt::format("N is below the smallest grid, {}^{}", p, s)};
    }
    return grid(n, s);
  }

  std::vector<sizing> explicit_sizes(std::size_t s) const override {
    std::vector<sizing> out;
    for (const std::uint64_t n : options_.panels) out.push_back(grid(n, s));
    return out;
  }
  std::string explicit_sizes_key() const override { return "panels"; }

  theoretical_rate theory(const integrand_class& f) const override {
    theoretical_rate rate = composite_rule_rate(rule_.order(), f);
    if (note_ != nullptr) note_(f, rule_.order(), rate);
    return rate;
  }

  double error_envelope(const integrand_info& f, const cell_size& size) const override {
    return jump_error_envelope(rule_, f, size.per_axis)
        .value_or(std::numeric_limits<double>::quiet_NaN());
  }

  // The Euler–Maclaurin expansion of the rule on f's end-point data (rules/euler_maclaurin.hpp):
  // the order of its first non-vanishing term, and the predicted error of every grid.
  std::optional<error_prediction> predict_error(const integrand_info& f) const override {
    auto expansion =
        euler_maclaurin_prediction::make(euler_maclaurin_rule::of(rule_, layout_.smallest), f);
    if (!expansion) return std::nullopt;
    const std::size_t s = f.dimension();
    const int lead = expansion->leading_order();
    error_prediction out;
    if (lead > 0) out.leading_slope = -static_cast<double>(lead) / static_cast<double>(s);
    out.superconvergent = lead == 0 || lead > expansion->rule_order();
    const std::string vanished = expansion->vanished();
    out.note = lead == 0 ? vanished + "; every end-point term through H" +
                               std::to_string(euler_maclaurin_orders) + " vanishes"
                         : (vanished.empty() ? std::string() : vanished + "; ") + "leading term " +
                               expansion->leading_term() +
                               (s > 1 ? fmt::format(", N^({}/{}) in N", -lead, s) : "");
    out.source = "docs/theory.md#euler-maclaurin-expansion; [Lyness & Ninham 1967]";
    out.coarse_grid_note = expansion->coarse_grid_text();
    if (!out.coarse_grid_note.empty()) {
      out.source += "; docs/theory.md#coarse-grid-term; [Trefethen & Weideman 2014]";
    }
    out.at = [expansion = std::move(*expansion), layout = layout_, s](std::uint64_t n) {
      predicted_cell cell;
      // Past 2^53 panels the count leaves the range the analysis holds exactly: no grid.
      cell.evaluations = n <= max_panels ? checked_power(layout.points(n), s).value_or(0) : 0;
      const euler_maclaurin_value v = expansion.at(n);
      cell.error = v.error;
      cell.next_change = v.next_change;
      cell.coarse_grid = v.coarse_grid;
      return cell;
    };
    return out;
  }

  summation summation_scheme() const override { return options_.accumulator; }

  // integrate() is weighted_sum over the rule's tensor grid: shared unless the accumulator is
  // the naive left-to-right sum.
  bool shares_chunks() const override {
    using grid = tensor_product_grid<decltype(rule_.nodes(std::uint64_t{1}))>;
    return weighted_sum_shares_chunks<grid>(options_.accumulator);
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const rule_result r =
        integrate(cell.function, rule_, cell.size.per_axis, context.threads, options_.accumulator);
    // A deterministic rule reports no standard error: coverage does not apply (NaN).
    repetition_result out;
    out.value = r.value;
    out.evaluations = r.evaluations;
    return out;
  }

 private:
  sizing grid(std::uint64_t n, std::size_t s) const {
    const std::uint64_t p = layout_.points(n);
    const auto evaluations = checked_power(p, s);
    if (!evaluations) {
      return {std::nullopt,
              fmt::format("n = {}: {}^{} evaluations do not fit in 64 bits", n, p, s)};
    }
    return {cell_size{*evaluations, n, p, rule_.order()}, {}};
  }

  Rule rule_;
  node_layout layout_;
  rule_options options_;
  note_fn note_;
};

constexpr node_layout one_node_per_panel{1, 0, 1, 1};
constexpr node_layout shared_end_nodes{1, 1, 1, 1};
constexpr node_layout simpson_pairs{1, 1, 2, 2};

constexpr std::array<option_doc, 2> rule_option_docs{{
    {"panels", "explicit panels n per axis (an integer or an increasing list), replacing budget.N"},
    {"accumulator",
     "how the N terms are summed: \"pairwise\" (default: pairwise per batch, Neumaier across "
     "batches), \"neumaier\", \"naive\" (one left-to-right double sum), \"long_double\"; the "
     "label gets the suffix, e.g. midpoint_naive"},
}};
constexpr std::array<option_doc, 3> gauss_option_docs{{
    rule_option_docs[0],
    rule_option_docs[1],
    {"m", "nodes per panel: 2 3 4 5 7 10 15 20 25 30 (default 3)"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

template <class Rule>
std::unique_ptr<const method> create_rule(
    const method_descriptor& d, option_reader& r, node_layout layout,
    typename tensor_rule_method<Rule>::note_fn note = nullptr) {
  return std::make_unique<tensor_rule_method<Rule>>(d, Rule{}, layout, read_rule_options(r, layout),
                                                    note);
}

void trapezoid_note(const integrand_class& f, int /*order*/, theoretical_rate& rate) {
  if (f.regularity == smoothness::analytic) {
    rate.note += "; exponential instead if f is periodic (docs/theory.md#exponential-convergence)";
  }
}

// Composite Gauss–Legendre with m nodes per panel and n panels: error O(n^-2m) for f ∈ C^2m
// (docs/theory.md#gauss-legendre; [Davis & Rabinowitz, §2.7]), so a fixed m is an algebraic rule
// of order r = 2m, and a kink, jump or √x caps it like any composite rule.
void gauss_note(const integrand_class& f, int order, theoretical_rate& rate) {
  rate.note = fmt::format("composite Gauss–Legendre, order 2m = {}; ", order) + rate.note;
  if (f.regularity == smoothness::analytic || f.regularity == smoothness::smooth) {
    rate.source = "docs/theory.md#gauss-legendre; [Davis & Rabinowitz, §2.7]";
  }
}

std::unique_ptr<const method> create_gauss_legendre(const method_descriptor& d, option_reader& r) {
  const auto& supported = gauss_legendre_rule::supported_points;
  std::string list;
  for (unsigned p : supported) list += fmt::format("{}{}", list.empty() ? "" : " ", p);
  const std::string what = fmt::format("one of {}", list);
  std::uint64_t m = 3;
  if (auto given = r.count("m", 1, gauss_legendre_rule::max_points, what)) {
    if (std::find(supported.begin(), supported.end(), *given) == supported.end()) {
      r.fail("m", fmt::format("expected {}, got {}", what, *given));
    }
    m = *given;
  }
  const node_layout layout{m, 0, 1, 1};
  rule_options options = read_rule_options(r, layout);
  return std::make_unique<tensor_rule_method<gauss_legendre_rule>>(
      d, gauss_legendre_rule(static_cast<unsigned>(m)), layout, std::move(options), gauss_note);
}

const std::array<method_descriptor, 6> descriptors{{
    {"left_rectangle", "composite left-endpoint rectangle rule, O(h)", method_kind::deterministic,
     rule_option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) {
       return create_rule<rectangle_rule<rectangle_side::left>>(d, r, one_node_per_panel);
     }},
    {"right_rectangle", "composite right-endpoint rectangle rule, O(h)", method_kind::deterministic,
     rule_option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) {
       return create_rule<rectangle_rule<rectangle_side::right>>(d, r, one_node_per_panel);
     }},
    {"midpoint", "composite midpoint rule, O(h^2)", method_kind::deterministic, rule_option_docs,
     fixed_only,
     [](const method_descriptor& d, option_reader& r) {
       return create_rule<midpoint_rule>(d, r, one_node_per_panel);
     }},
    {"trapezoid", "composite trapezoid rule, O(h^2)", method_kind::deterministic, rule_option_docs,
     fixed_only,
     [](const method_descriptor& d, option_reader& r) {
       return create_rule<trapezoid_rule>(d, r, shared_end_nodes, trapezoid_note);
     }},
    {"simpson", "composite Simpson rule (n even), O(h^4)", method_kind::deterministic,
     rule_option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) {
       return create_rule<simpson_rule>(d, r, simpson_pairs);
     }},
    {"gauss_legendre", "composite m-point Gauss-Legendre rule, O(h^2m)", method_kind::deterministic,
     gauss_option_docs, fixed_only, create_gauss_legendre},
}};

}  // namespace

std::span<const method_descriptor> tensor_rule_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
