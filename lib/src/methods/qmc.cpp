// Randomized quasi-Monte Carlo as methods: `sobol`, `halton` and `lattice`, each the sample mean
// of f over a quasi-Monte Carlo set of estimators/point_set_catalogue.hpp with the method's own
// keys (docs/theory.md#quasi-monte-carlo):
//   randomization     sobol: "owen" (default), "fast_owen", "lms_shift", "shift", "none";
//                     halton: "owen" (default), "permutation", "none";
//                     lattice: "shift" (default), "none". "none" is the deterministic set, run once
//                     per cell like a rule.
//   periodization     lattice: "none" (default) or "baker".
//   allow_any_n       sobol: use every N as it is (the first N points of the sequence). Without
//                     it N maps to the largest 2^m ≤ N, as the tensor rules map N to the largest
//                     grid: a scrambled net needs N = 2^m, and a ladder with other values would
//                     otherwise measure the anti-pattern of docs/theory.md#sobol-anti-patterns.
//   drop_first_point  sobol: start at point 1 (Boost's sobol_engine does): the other anti-pattern.
//   points            explicit N per cell (an increasing list), replacing budget.N; each must be
//                     2^m where the set needs it, else the key fails naming the nearest valid
//                     sizes.
// The lattice maps N to the largest 2^m ≤ N up to 2^20 (its generating vector's range); Halton
// takes N as it is.
//
// Error bars: one randomization cannot estimate its own error, so every repetition is an
// independent randomization (its own Philox stream) and the cell's error estimate and coverage
// come from their spread (error_bars::replicates, analysis/cell_statistics.hpp;
// docs/theory.md#replicate-error-bars). A point set's σ̂²/N is never reported for these points.
// Beside the error, cells of N ≤ 1024 carry the L2 discrepancies of their points
// (sampling/discrepancy.hpp), computed outside the timed run (measure_points).
#include "families.hpp"

#include "quadmc/sampling/discrepancy.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <memory>
#include <vector>

namespace quadmc::methods {
namespace {

// Cells up to this N carry discrepancy columns: O(N²·s) per repetition (about 5 ms at s = 8 for
// N = 1024, 16 times that at 4096, which would cost more than the integration itself).
constexpr std::uint64_t discrepancy_max_points = 1024;

struct qmc_options {
  point_set_options set;
  bool randomization_given = false;
  bool periodization_given = false;
  std::vector<std::uint64_t> points;
};

class qmc_method final : public method {
 public:
  qmc_method(const method_descriptor& d, const point_set_entry& set, qmc_options options)
      : method(d), set_(&set), options_(std::move(options)) {}

  method_kind kind() const override {
    return set_->randomization_of(options_.set) == randomization::none ? method_kind::deterministic
                                                                       : method_kind::randomized;
  }

  quadmc::error_bars error_bars() const override {
    return error_bars_of(set_->errors_with(options_.set));
  }

  std::string label_suffix() const override {
    std::string out;
    if (options_.randomization_given) out += fmt::format("_{}", to_string(*options_.set.random));
    if (options_.periodization_given) out += fmt::format("_{}", to_string(options_.set.periodic));
    if (options_.set.allow_any_n) out += "_any_n";
    if (options_.set.drop_first_point) out += "_drop_first";
    return out;
  }

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s <= set_->max_dimension) return std::nullopt;
    return fmt::format("the {} points have at most {} dimensions; the integrand has s = {}",
                       set_->name, set_->max_dimension, f.s);
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (s > set_->max_dimension) {
      return {std::nullopt, fmt::format("s = {} is above the {} points' {} dimensions", s,
                                        set_->name, set_->max_dimension)};
    }
    const point_count counts = options_.set.allow_any_n ? point_count::any : set_->counts;
    const std::uint64_t n = largest_point_count(counts, N, s).points;
    const std::uint64_t most = max_point_count(*set_, options_.set);
    if (n > most) {
      return {std::nullopt,
              fmt::format("N = {} is above the largest {} set, {} points", N, set_->name, most)};
    }
    return {cell_size{n, 0, 0, 0}, {}};
  }

  std::vector<sizing> explicit_sizes(std::size_t) const override {
    std::vector<sizing> out;
    for (const std::uint64_t n : options_.points) out.push_back({cell_size{n, 0, 0, 0}, {}});
    return out;
  }
  std::string explicit_sizes_key() const override { return "points"; }

  theoretical_rate theory(const integrand_class& f) const override {
    const randomization r = *set_->randomization_of(options_.set);
    if (set_->name == "lattice") {
      theoretical_rate rate =
          shifted_lattice_rate(f, options_.set.periodic == periodization::baker);
      if (r == randomization::none) rate.note = "unshifted lattice (deterministic); " + rate.note;
      return rate;
    }
    if (set_->name == "halton") {
      return low_discrepancy_rate(
          f,
          r == randomization::none ? "Halton points"
                                   : fmt::format("{}-randomized Halton points, no "
                                                 "faster rate proven",
                                                 to_string(r)),
          "docs/theory.md#halton; [Halton 1960]; [Niederreiter 1992, Thm 3.6]");
    }
    // Sobol'.
    switch (r) {
      case randomization::owen:
      case randomization::lms_shift:
        if (options_.set.drop_first_point) return broken_net_rate(f, "first point dropped");
        if (options_.set.allow_any_n) return broken_net_rate(f, "N not 2^m (allow_any_n)");
        return scrambled_net_rate(f);
      case randomization::fast_owen:
        return {std::nullopt,
                "hash-based, not exactly nested uniform: Owen's rates are not proven for it",
                "docs/theory.md#scrambled-nets; [Burley 2020]"};
      case randomization::shift:
        return low_discrepancy_rate(f, "digital shift: one shift shared by all points",
                                    "docs/theory.md#digital-shift; [Dick & Pillichshammer 2010]");
      default:
        return low_discrepancy_rate(f, "unrandomized Sobol' points",
                                    "docs/theory.md#digital-shift; [Niederreiter 1992, Thm 4.10]");
    }
  }

  bool shares_chunks() const override { return sample_mean_shares_chunks; }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const estimate e = set_->monte_carlo(cell.function, {context.seed, cell.stream},
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
    const std::uint64_t n = cell.size.evaluations;
    if (n > discrepancy_max_points) return;
    const std::size_t s = cell.function.dimension();
    std::vector<double> x;
    x.reserve(n * s);
    set_->points(
        s, n, {context.seed, cell.stream},
        [&](std::uint64_t, std::span<const double> batch) {
          x.insert(x.end(), batch.begin(), batch.end());
        },
        options_.set);
    const l2_discrepancies d = discrepancies(x, s);
    result.l2_star_discrepancy = d.l2_star;
    result.centered_discrepancy = d.centered;
    result.wraparound_discrepancy = d.wraparound;
  }

 private:
  const point_set_entry* set_;
  qmc_options options_;
};

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
                      set.name, set.name == "sobol" ? "; allow_any_n = true takes N as it is" : "",
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

std::unique_ptr<const method> create_qmc(const method_descriptor& d, option_reader& r,
                                         std::string_view set_name) {
  const point_set_entry& set = *find_point_set(set_name);
  qmc_options o;
  std::vector<std::string_view> names;
  for (const randomization x : set.randomizations) names.push_back(to_string(x));
  if (auto name = r.choice("randomization", names)) {
    o.set.random = parse_randomization(*name);
    o.randomization_given = true;
  }
  if (set.name == "lattice") {
    constexpr std::array<std::string_view, 2> periodizations{"none", "baker"};
    if (auto p = r.choice("periodization", periodizations)) {
      o.set.periodic = *p == "baker" ? periodization::baker : periodization::none;
      o.periodization_given = true;
    }
  }
  if (set.name == "sobol") {
    o.set.allow_any_n = r.boolean("allow_any_n").value_or(false);
    o.set.drop_first_point = r.boolean("drop_first_point").value_or(false);
  }
  o.points = read_points(r, set, o.set);
  return std::make_unique<qmc_method>(d, set, std::move(o));
}

constexpr std::array<option_doc, 4> sobol_docs{{
    {"randomization",
     "\"owen\" (default: nested uniform scrambling), \"fast_owen\" (Burley's hash, not exactly "
     "nested), \"lms_shift\" (linear matrix scramble + digital shift), \"shift\" (digital shift), "
     "\"none\" (deterministic, one run per cell); the label gets \"_<randomization>\""},
    {"allow_any_n",
     "true: use each N as it is (no net unless N = 2^m); default false: N maps to the largest "
     "2^m <= N; the label gets \"_any_n\""},
    {"drop_first_point",
     "true: start at point 1, not the origin (the anti-pattern); the label gets \"_drop_first\""},
    {"points",
     "explicit N per cell (an integer or an increasing list), replacing budget.N; 2^m "
     "unless allow_any_n"},
}};
constexpr std::array<option_doc, 2> halton_docs{{
    {"randomization",
     "\"owen\" (default: nested scrambling in each base), \"permutation\" (random digit "
     "permutations per base and digit), \"none\" (deterministic); the label gets the suffix"},
    {"points", "explicit N per cell (an integer or an increasing list), replacing budget.N"},
}};
constexpr std::array<option_doc, 3> lattice_docs{{
    {"randomization",
     "\"shift\" (default: one uniform shift modulo 1), \"none\" (the lattice itself, "
     "deterministic); the label gets the suffix"},
    {"periodization",
     "\"none\" (default) or \"baker\" (the tent transform 1 - |2x - 1|); the label gets the "
     "suffix"},
    {"points",
     "explicit N per cell (2^m <= 2^20, an integer or an increasing list), replacing "
     "budget.N"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

const std::array<method_descriptor, 3> descriptors{{
    {"sobol",
     "randomized Sobol' points (Joe-Kuo directions, Gray-code order), N = 2^m; error bars from "
     "replicates",
     method_kind::randomized, sobol_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) { return create_qmc(d, r, "sobol"); }},
    {"halton", "randomized Halton points in the first s prime bases; error bars from replicates",
     method_kind::randomized, halton_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) { return create_qmc(d, r, "halton"); }},
    {"lattice",
     "randomly shifted rank-1 lattice (Cools-Kuo-Nuyens vector), N = 2^m <= 2^20; error bars "
     "from replicates",
     method_kind::randomized, lattice_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) { return create_qmc(d, r, "lattice"); }},
}};

}  // namespace

std::span<const method_descriptor> qmc_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
