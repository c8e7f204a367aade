// Randomized quasi-Monte Carlo as methods: `sobol`, `halton`, `lattice`, `padded_sobol` and
// `pmj02`, each the sample mean of f over the quasi-Monte Carlo set of
// estimators/point_set_catalogue.hpp it is named after (docs/theory.md#quasi-monte-carlo). Its keys
// are the set's own (its point_set_option table: `randomization`, the lattice's `periodization`,
// Sobol's `allow_any_n`, `drop_first_point` and `interlacing`; `quadmc list` prints each with its
// values) and the label gets the values given, plus
//   points            explicit N per cell (an increasing list), replacing budget.N; each must be
//                     2^m where the set needs it, else the key fails naming the nearest valid
//                     sizes.
// Without allow_any_n, N maps to the largest count the set holds (2^m ≤ N for Sobol' and the
// lattice, up to 2^20 for the lattice's generating vector), as the tensor rules map N to the
// largest grid: a scrambled net needs N = 2^m, and a ladder with other values would otherwise
// measure the anti-pattern of docs/theory.md#sobol-anti-patterns. Halton takes N as it is. A
// randomization "none" is the deterministic set, run once per cell like a rule. The rate is the
// set's (point_set_entry::theory_of) in the building blocks of analysis/theoretical_rate.hpp.
//
// Error bars: one randomization cannot estimate its own error, so every repetition is an
// independent randomization (its own Philox stream) and the cell's error estimate and coverage
// come from their spread (error_bars::replicates, analysis/cell_statistics.hpp;
// docs/theory.md#replicate-error-bars). A point set's σ̂²/N is never reported for these points.
// With `replicate_estimator = "mean" | "median"` one estimate is instead the mean or the median
// of `replicate_count` = k independent randomizations of n = N/k points each (n the largest
// count the set holds there), with the error bar of estimators/replicate_estimator.hpp
// (error_bars::own; docs/theory.md#replicate-estimators): N stays the evaluations spent, so a
// ladder compares the combined estimate with one randomization of all N points.
// Beside the error, cells of N ≤ 1024 carry the L2 discrepancies of their points
// (sampling/discrepancy.hpp), computed outside the timed run (measure_points).
#include "families.hpp"
#include "stopping.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/replicate_estimator.hpp"
#include "quadmc/sampling/discrepancy.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <bit>
#include <memory>
#include <string>
#include <vector>

namespace quadmc::methods {
namespace {

// Cells up to this N carry discrepancy columns: O(N²·s) per repetition (about 5 ms at s = 8 for
// N = 1024, 16 times that at 4096, which would cost more than the integration itself), and only
// while N²·s ≤ 2^24 (N = 1024 at s = 16; N ≤ 128 at s = 1024, where N = 1024 would take seconds
// per repetition on one thread, for a column nobody can read at that s).
constexpr std::uint64_t discrepancy_max_points = 1024;
constexpr std::uint64_t discrepancy_max_pair_coordinates = std::uint64_t{1} << 24;

// k of replicate_estimator when replicate_count is not given: odd, for the median's middle value.
// [Pan & Owen 2023] let k grow like m = log2 n for their rate; 11 covers the ladders up to
// n = 2^11 in that sense, and a user with a longer ladder sets replicate_count.
constexpr std::uint64_t default_replicate_count = 11;

struct qmc_options {
  point_set_options set;
  std::string label_suffix;  // the set's options given, in its order (point_set_option)
  std::vector<std::uint64_t> points;
  std::optional<stopping_choice> stopping;     // the sets that may run to a tolerance
  std::optional<replicate_estimator> combine;  // one estimate from k randomizations
  std::uint64_t replicate_count = default_replicate_count;
};

// A building block's rate with the set's own words before its note.
theoretical_rate with_prefix(const std::string& prefix, theoretical_rate rate) {
  if (!prefix.empty()) rate.note = prefix + "; " + rate.note;
  return rate;
}

class qmc_method final : public method {
 public:
  qmc_method(const method_descriptor& d, const point_set_entry& set, qmc_options options)
      : method(d), set_(&set), options_(std::move(options)) {}

  method_kind kind() const override {
    return set_->randomization_of(options_.set) == randomization::none ? method_kind::deterministic
                                                                       : method_kind::randomized;
  }

  quadmc::error_bars error_bars() const override {
    // A combined estimate carries its own error bar (replicate_estimator.hpp).
    if (options_.combine) return quadmc::error_bars::own;
    return error_bars_of(set_->errors_with(options_.set));
  }

  std::string label_suffix() const override {
    std::string combined;
    if (options_.combine) {
      combined = options_.replicate_count == default_replicate_count
                     ? fmt::format("_{}", to_string(*options_.combine))
                     : fmt::format("_{}{}", to_string(*options_.combine), options_.replicate_count);
    }
    return options_.label_suffix + combined +
           (options_.stopping ? options_.stopping->label_suffix() : "");
  }

  std::optional<control_refusal> refuses(cell_control control) const override {
    if (options_.combine && control == cell_control::tolerance) {
      return control_refusal{
          "replicate_estimator",
          "expected only at fixed N (the stopping rules combine their randomizations "
          "themselves), got it with control = \"tolerance\""};
    }
    return options_.stopping ? options_.stopping->refuses(control) : std::nullopt;
  }

  sizing tolerance_size_for(std::uint64_t budget, std::size_t s) const override {
    if (set_->max_dimension != 0 && s > set_->max_dimension) return size_for(budget, s);
    return stopping_sizing(*options_.stopping, *set_, options_.set, budget, s);
  }

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (set_->max_dimension == 0) return std::nullopt;
    // An interlaced set (interlacing α > 1) draws α·s of the tables' dimensions.
    if (options_.set.interlacing > 1) {
      const std::string problem = dimension_problem(*set_, f.s, options_.set);
      if (problem.empty()) return std::nullopt;
      return fmt::format("the integrand has s = {}: {}", f.s, problem);
    }
    if (f.s <= set_->max_dimension) return std::nullopt;
    return fmt::format("the {} points have at most {} dimensions; the integrand has s = {}",
                       set_->name, set_->max_dimension, f.s);
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (options_.set.interlacing > 1) {
      if (std::string problem = dimension_problem(*set_, s, options_.set); !problem.empty()) {
        return {std::nullopt, std::move(problem)};
      }
    }
    if (set_->max_dimension != 0 && s > set_->max_dimension) {
      return {std::nullopt, fmt::format("s = {} is above the {} points' {} dimensions", s,
                                        set_->name, set_->max_dimension)};
    }
    // A combined estimate spends N on k randomizations of N/k points each.
    const std::uint64_t k = combined_count();
    if (N < k) {
      return {std::nullopt, fmt::format("N = {} is below replicate_count = {} randomizations of "
                                        "one point",
                                        N, k)};
    }
    const point_count counts = options_.set.allow_any_n ? point_count::any : set_->counts;
    const std::uint64_t n = largest_point_count(counts, N / k, s).points;
    const std::uint64_t most = max_point_count(*set_, options_.set);
    if (n > most) {
      return {std::nullopt, fmt::format("N = {} is above the largest {} set, {} points", N / k,
                                        set_->name, most)};
    }
    return {cell_size{k * n, 0, 0, 0}, {}};
  }

  // The randomizations one estimate spends its N on: k with replicate_estimator, else one.
  std::uint64_t combined_count() const noexcept {
    return options_.combine ? options_.replicate_count : 1;
  }

  std::vector<sizing> explicit_sizes(std::size_t) const override {
    std::vector<sizing> out;
    // With replicate_estimator each point count is n of one randomization; the cell spends k·n.
    for (const std::uint64_t n : options_.points) {
      out.push_back({cell_size{combined_count() * n, 0, 0, 0}, {}});
    }
    return out;
  }
  std::string explicit_sizes_key() const override { return "points"; }

  theoretical_rate theory(const integrand_class& f) const override {
    if (options_.combine == replicate_estimator::median) {
      // Proven rates need k to grow with m ([Pan & Owen 2023]); at a fixed k none is.
      return {std::nullopt,
              fmt::format("median of k = {} randomizations: super-polynomial for analytic f in "
                          "s = 1 under random linear scrambling as k grows like log2 n, no proven "
                          "slope at a fixed k",
                          options_.replicate_count),
              "docs/theory.md#replicate-estimators; [Pan & Owen 2023]"};
    }
    // The mean of a fixed number k of randomizations of N/k points: the rate of one.
    const point_set_theory said = *set_->theory_of(options_.set);
    if (said.padded && f.s > 2) {
      return root_n_rate(f,
                         "padding: only the pairs of dimensions are nets, associated at random; "
                         "plain MC rate unless f is a sum of 2D parts",
                         "docs/theory.md#padded-jittered; [Pharr et al. 2023, §8.5]; [Owen 1998]");
    }
    switch (said.basis) {
      case rate_basis::scrambled_net:
        return with_prefix(said.note, scrambled_net_rate(f));
      case rate_basis::broken_net:
        return broken_net_rate(f, said.note);
      case rate_basis::low_discrepancy:
        return low_discrepancy_rate(f, said.note, std::string(said.source));
      case rate_basis::shifted_lattice:
        return with_prefix(
            said.note,
            shifted_lattice_rate(f, {said.periodization, said.periodic_order, said.weighted}));
      case rate_basis::interlaced_net:
        return interlaced_net_rate(f, said.interlacing, said.scrambled);
      case rate_basis::unproven:
        break;
    }
    return {std::nullopt, said.note, std::string(said.source)};
  }

  // A combined estimate's k runs are computed whole on every process (process_local).
  bool shares_chunks() const override { return !options_.combine && sample_mean_shares_chunks; }
  bool shares_chunks_at(cell_control control) const override {
    return control == cell_control::tolerance ? stopping_shares_chunks(*options_.stopping, *set_)
                                              : shares_chunks();
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    if (cell.control == cell_control::tolerance) {
      return run_stopping(*options_.stopping, *set_, options_.set, cell, context);
    }
    if (options_.combine) return run_combined(cell, context);
    const estimate e = set_->monte_carlo(cell.function, {context.seed, cell.stream, context.rng},
                                         cell.size.evaluations, context.threads, options_.set);
    // No std_error nor error_estimate: one run of these points has none (e.std_error is NaN);
    // the replicates give them (error_bars()).
    repetition_result out;
    out.value = e.value;
    out.evaluations = e.evaluations;
    return out;
  }

  void measure_points(const method_cell& cell, const run_context& context,
                      repetition_result& result) const override {
    // A cell to a tolerance spends what its rule decides; its size is only the budget. A
    // combined cell's points are k sets, none of them N points.
    if (cell.control == cell_control::tolerance || options_.combine) return;
    const std::uint64_t n = cell.size.evaluations;
    const std::size_t s = cell.function.dimension();
    if (n > discrepancy_max_points || n * n * s > discrepancy_max_pair_coordinates) return;
    // A weighted periodization (c0 … c3sin) averages g over the lattice points themselves: the
    // points measured are those (docs/theory.md#lattice-periodizations).
    point_set_options measured = options_.set;
    if (is_weighted(measured.periodic)) measured.periodic = periodization::none;
    std::vector<double> x;
    x.reserve(n * s);
    set_->points(
        s, n, {context.seed, cell.stream, context.rng},
        [&](std::uint64_t, std::span<const double> batch) {
          x.insert(x.end(), batch.begin(), batch.end());
        },
        measured);
    const l2_discrepancies d = discrepancies(x, s);
    result.l2_star_discrepancy = d.l2_star;
    result.centered_discrepancy = d.centered;
    result.wraparound_discrepancy = d.wraparound;
  }

 private:
  // k randomizations of n = N/k points, randomization r from the Philox stream
  // stream_id({cell stream, r}), combined by replicate_estimator.hpp.
  repetition_result run_combined(const method_cell& cell, const run_context& context) const {
    const std::uint64_t k = options_.replicate_count;
    const std::uint64_t n = cell.size.evaluations / k;
    std::vector<double> values(k);
    repetition_result out;
    for (std::uint64_t r = 0; r < k; ++r) {
      const estimate e =
          set_->monte_carlo(cell.function, {context.seed, stream_id({cell.stream, r}), context.rng},
                            n, context.threads, options_.set);
      values[r] = e.value;
      out.evaluations += e.evaluations;
    }
    const combined_replicates c = combine_replicates(values, *options_.combine);
    out.value = c.value;
    out.std_error = c.std_error;
    out.error_estimate = c.error_estimate;
    return out;
  }

  const point_set_entry* set_;
  qmc_options options_;
};

// replicate_estimator and replicate_count: both on a randomized set only, the count odd for a
// median.
void read_replicate_estimator(option_reader& r, const point_set_entry& set, qmc_options& o) {
  constexpr std::array<std::string_view, 2> estimators{"mean", "median"};
  if (auto how = r.choice("replicate_estimator", estimators)) {
    o.combine = *how == "median" ? replicate_estimator::median : replicate_estimator::mean;
    if (set.randomization_of(o.set) == randomization::none) {
      r.fail("replicate_estimator",
             fmt::format("expected a randomized set (the {} points with randomization \"none\" "
                         "are one deterministic set: nothing to combine), got replicate_estimator "
                         "= \"{}\"",
                         set.name, *how));
    }
  }
  const auto k = r.count("replicate_count", 2, 1U << 16, "k, between 2 and 65536");
  if (!k) return;
  if (!o.combine) {
    r.fail("replicate_count",
           "expected only with replicate_estimator (the randomizations one estimate combines)");
  }
  if (*o.combine == replicate_estimator::median && (*k < 3 || *k % 2 == 0)) {
    r.fail("replicate_count",
           fmt::format("expected an odd k ≥ 3 for replicate_estimator = \"median\" (its middle "
                       "value), got {}",
                       *k));
  }
  o.replicate_count = *k;
}

// The `points` key: explicit N, increasing, each one the set can hold with these options.
std::vector<std::uint64_t> read_points(option_reader& r, const point_set_entry& set,
                                       const point_set_options& o) {
  const std::uint64_t most = max_point_count(set, o);
  const std::string what = fmt::format("a point count between 1 and {}", most);
  auto given = r.counts("points", 1, most, 256, what);
  if (!given) return {};
  const bool power_of_two = !o.allow_any_n && set.counts == point_count::power_of_two;
  for (std::size_t i = 0; i < given->size(); ++i) {
    const std::uint64_t n = (*given)[i];
    if (power_of_two && !std::has_single_bit(n)) {
      const std::uint64_t below = std::bit_floor(n);
      r.fail_element(
          "points", i,
          fmt::format("expected a power of two (the {} points need N = 2^m{}), got {}; "
                      "nearest valid sizes {} and {}",
                      set.name, set.takes_any_prefix ? "; allow_any_n = true takes N as it is" : "",
                      n, below, below << 1));
    }
    if (i > 0 && n <= (*given)[i - 1]) {
      r.fail_element(
          "points", i,
          fmt::format("point counts must increase, got {} after {}", n, (*given)[i - 1]));
    }
  }
  return std::move(*given);
}

// An integer choice (point_set_option::integer): a TOML integer whose decimal text is one of the
// key's choices, as that text ("2" for interlacing = 2); a string "2" fails as not an integer.
std::optional<std::string> read_integer_choice(option_reader& r, const point_set_option& key) {
  const std::string what = fmt::format("an integer, one of {}", fmt::join(key.choices, ", "));
  // Any count reads here (2^32 keeps the double → integer conversion exact) so that a number
  // outside the choices fails with them listed.
  const auto value = r.count(key.key, 0, std::uint64_t{1} << 32, what);
  if (!value) return std::nullopt;
  std::string text = std::to_string(*value);
  if (std::find(key.choices.begin(), key.choices.end(), text) == key.choices.end()) {
    r.fail(key.key, fmt::format("expected {}, got {}", what, text));
  }
  return text;
}

// Reads the set's own keys (its point_set_option table) as the method's options, then `points`.
// A quasi-Monte Carlo method is named after its set.
std::unique_ptr<const method> create_qmc(const method_descriptor& d, option_reader& r) {
  const point_set_entry& set = *find_point_set(d.name);
  qmc_options o;
  std::vector<std::string_view> values(set.options.size());
  std::vector<std::string> chosen(set.options.size());
  for (std::size_t i = 0; i < set.options.size(); ++i) {
    const point_set_option& key = set.options[i];
    if (key.is_flag()) {
      if (r.boolean(key.key).value_or(false)) {
        values[i] = "true";
        o.label_suffix += key.flag_label;
      }
    } else if (key.integer) {
      if (auto value = read_integer_choice(r, key)) {
        chosen[i] = std::move(*value);
        values[i] = chosen[i];
        o.label_suffix += fmt::format("_{}{}", key.key, chosen[i]);
      }
    } else if (auto value = r.choice(key.key, key.choices)) {
      chosen[i] = std::move(*value);
      values[i] = chosen[i];
      o.label_suffix += "_" + chosen[i];
    }
  }
  o.set = set.options_of(values);
  // A randomization the interlaced net refuses (fast_owen, lms_shift), named at plan time.
  if (const std::string problem = interlacing_problem(set, o.set); !problem.empty()) {
    r.fail("interlacing",
           fmt::format("randomization \"{}\" with interlacing = {}: expected {}",
                       to_string(*set.randomization_of(o.set)), o.set.interlacing, problem));
  }
  o.points = read_points(r, set, o.set);
  read_replicate_estimator(r, set, o);
  if (d.supports(cell_control::tolerance)) o.stopping = read_stopping(r, set, o.set);
  return std::make_unique<qmc_method>(d, set, std::move(o));
}

// One method per quasi-Monte Carlo set: its name (the set's), description and what its
// `points` key takes; the set's own keys come before `points`.
struct qmc_method_spec {
  std::string_view name;
  std::string_view description;
  std::string_view points;
  bool to_tolerance = false;  // control = "tolerance" with a stopping rule (stopping.hpp)
};
constexpr std::array<qmc_method_spec, 5> specs{{
    {"sobol",
     "randomized Sobol' points (Joe-Kuo directions, Gray-code order), N = 2^m; error bars from "
     "replicates",
     "explicit N per cell (an integer or an increasing list), replacing budget.N; 2^m "
     "unless allow_any_n",
     true},
    {"halton", "randomized Halton points in the first s prime bases; error bars from replicates",
     "explicit N per cell (an integer or an increasing list), replacing budget.N", true},
    {"padded_sobol",
     "scrambled 2D Sobol' nets per pair of dimensions, shuffled across pairs (pbrt-v4's "
     "PaddedSobolSampler), N = 2^m; error bars from replicates",
     "explicit N per cell (2^m, an integer or an increasing list), replacing budget.N"},
    {"pmj02",
     "progressive multi-jittered (0,2) sequence per pair of dimensions, padded, any N; error "
     "bars from replicates",
     "explicit N per cell (an integer or an increasing list), replacing budget.N"},
    {"lattice",
     "randomly shifted rank-1 lattice (Cools-Kuo-Nuyens vector), N = 2^m <= 2^20; error bars "
     "from replicates",
     "explicit N per cell (2^m <= 2^20, an integer or an increasing list), replacing "
     "budget.N",
     true},
}};
constexpr std::array<option_doc, 2> replicate_docs{{
    {"replicate_estimator",
     "\"mean\" | \"median\": one estimate from replicate_count randomizations of N/k points, "
     "their mean (error bar s/sqrt(k)) or median (Pan & Owen; error bar from order statistics); "
     "absent: one randomization of N points"},
    {"replicate_count",
     "k randomizations per estimate with replicate_estimator (default 11; odd for the median)"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};
constexpr std::array<cell_control, 2> fixed_or_tolerance{cell_control::fixed_size,
                                                         cell_control::tolerance};

// The descriptors with their option docs, built from the specs and the catalogue's constant
// entries on first use: the registry may ask for them from another file's static initializer
// (the peers' add_methods), before this file's dynamic initialization would have run.
struct qmc_descriptors {
  std::array<std::vector<option_doc>, specs.size()> docs;
  std::vector<method_descriptor> descriptors;

  qmc_descriptors() {
    for (std::size_t i = 0; i < specs.size(); ++i) {
      for (const point_set_option& o : find_point_set(specs[i].name)->options) {
        docs[i].push_back({o.key, o.meaning});
      }
      docs[i].push_back({"points", specs[i].points});
      for (const option_doc& o : replicate_docs) docs[i].push_back(o);
      if (specs[i].to_tolerance) {
        for (const option_doc& o : stopping_docs) docs[i].push_back(o);
      }
      descriptors.push_back({specs[i].name, specs[i].description, method_kind::randomized, docs[i],
                             specs[i].to_tolerance
                                 ? std::span<const cell_control>(fixed_or_tolerance)
                                 : std::span<const cell_control>(fixed_only),
                             create_qmc});
    }
  }
};

}  // namespace

std::span<const method_descriptor> qmc_methods() noexcept {
  static const qmc_descriptors built;
  return built.descriptors;
}

}  // namespace quadmc::methods
