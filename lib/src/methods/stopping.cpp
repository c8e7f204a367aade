// The `stopping` key of the sample-mean methods and a cell run by its rule (stopping.hpp).
#include "stopping.hpp"

#include "families.hpp"

#include "quadmc/core/rng.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace quadmc::methods {
namespace {

// The guaranteed digital rule keeps every value for its Walsh transform: 2^26 doubles (512 MiB)
// is the most a cell may hold, whatever the budget (the lattice's own maximum, 2^20, is lower).
constexpr std::uint64_t guaranteed_max_values = std::uint64_t{1} << 26;

constexpr std::array<std::string_view, 3> rule_names{"replicates", "guaranteed", "clt"};

std::string_view name_of(stopping_rule r) noexcept {
  return rule_names[static_cast<std::size_t>(r)];
}

bool is_random(const point_set_entry& set, const point_set_options& o) {
  const auto r = set.randomization_of(o);
  return !r || *r != randomization::none;
}

// The doubling rules draw the lattice's points in radical-inverse order themselves; the weighted
// periodizations (docs/theory.md#lattice-periodizations) are a change of variables of the
// fixed-size sample mean that they do not apply.
std::string weighted_problem(const point_set_options& o) {
  return fmt::format(
      "periodization = \"{}\" weights each point by ∏φ', which the doubling rules do not apply "
      "to the lattice they extend: use periodization = \"none\" or \"baker\"",
      to_string(o.periodic));
}

// Why `rule` cannot run on the set with these options; empty when it can.
std::string rule_problem(stopping_rule rule, const point_set_entry& set,
                         const point_set_options& o) {
  const bool own = set.errors_with(o) == error_source::own;
  switch (rule) {
    case stopping_rule::replicates:
      if (!set.extensible()) {
        return fmt::format(
            "the {} points at 2N are not those at N and N more (their strata change with N), so "
            "N cannot be doubled keeping what was spent: use stopping = \"clt\"",
            set.name);
      }
      if (!is_random(set, o)) return "randomization = \"none\" leaves nothing to replicate";
      if (is_weighted(o.periodic)) return weighted_problem(o);
      return {};
    case stopping_rule::guaranteed:
      if (set.coefficients == coefficient_transform::walsh) {
        const auto r = *set.randomization_of(o);
        if (r != randomization::shift && r != randomization::lms_shift) {
          return fmt::format(
              "the guaranteed digital rule bounds the error by the values' Walsh coefficients on "
              "the dual net, which holds for a digitally shifted net: use randomization = "
              "\"lms_shift\" (QMCPy's default) or \"shift\", not \"{}\"",
              to_string(r));
        }
        if (o.allow_any_n || o.drop_first_point) {
          return "the guaranteed digital rule needs the net itself (no allow_any_n, no "
                 "drop_first_point)";
        }
        return {};
      }
      if (set.coefficients == coefficient_transform::fourier) {
        if (!is_random(set, o)) return "the guaranteed lattice rule needs the random shift";
        if (is_weighted(o.periodic)) return weighted_problem(o);
        return {};
      }
      if (own && set.extensible()) return {};  // independent points: Berry–Esseen
      return fmt::format(
          "no guaranteed rule for the {} points (guaranteed: sobol with a digital shift, lattice, "
          "plain_mc)",
          set.name);
    case stopping_rule::clt:
      if (!own) {
        return fmt::format(
            "one run of the {} points has no error estimate of its own for the pilot to size "
            "from: use stopping = \"replicates\"",
            set.name);
      }
      return {};
  }
  return "unknown rule";
}

// The keys each rule reads.
bool reads(stopping_rule rule, const point_set_entry& set, std::string_view key) {
  if (key == "stopping" || key == "n_init") return true;
  const bool net_rule =
      rule == stopping_rule::guaranteed && set.coefficients != coefficient_transform::none;
  if (key == "replications") return rule == stopping_rule::replicates;
  if (key == "fudge" || key == "r_lag") return net_rule;
  return !net_rule;  // alpha, inflate
}

}  // namespace

std::string stopping_choice::label_suffix() const {
  return given && rule ? fmt::format("_{}", name_of(*rule)) : std::string();
}

std::optional<control_refusal> stopping_choice::refuses(cell_control control) const {
  if (control != cell_control::tolerance) {
    if (keys.empty()) return std::nullopt;
    return control_refusal{keys.front(),
                           fmt::format("expected only with control = \"tolerance\" (a stopping "
                                       "rule's key), got it with control = \"{}\"",
                                       to_string(control))};
  }
  if (!rule) return control_refusal{"control", "control = \"tolerance\": " + why_none};
  return std::nullopt;
}

stopping_choice read_stopping(option_reader& r, const point_set_entry& set,
                              const point_set_options& options) {
  stopping_choice c;
  for (const option_doc& d : stopping_docs) {
    if (r.has(d.key)) c.keys.emplace_back(d.key);
  }
  if (auto name = r.choice("stopping", rule_names)) {
    c.given = true;
    for (std::size_t i = 0; i < rule_names.size(); ++i) {
      if (rule_names[i] == *name) c.rule = static_cast<stopping_rule>(i);
    }
    if (const std::string why = rule_problem(*c.rule, set, options); !why.empty()) {
      r.fail("stopping", fmt::format("stopping = \"{}\" on {}: {}", *name, set.name, why));
    }
  } else {
    for (const stopping_rule rule : {stopping_rule::clt, stopping_rule::replicates}) {
      if (rule_problem(rule, set, options).empty()) {
        c.rule = rule;
        break;
      }
    }
    if (!c.rule) {
      c.why_none = fmt::format("no stopping rule fits the {} points: {}; {}", set.name,
                               rule_problem(stopping_rule::clt, set, options),
                               rule_problem(stopping_rule::replicates, set, options));
      return c;
    }
  }
  for (const std::string& key : c.keys) {
    if (!reads(*c.rule, set, key)) {
      r.fail(key, fmt::format("expected only with a rule that reads it, got it with stopping = "
                              "\"{}\" on {}",
                              name_of(*c.rule), set.name));
    }
  }

  const bool net_rule =
      *c.rule == stopping_rule::guaranteed && set.coefficients != coefficient_transform::none;
  const bool doubling = *c.rule == stopping_rule::replicates || net_rule;
  if (auto n = r.count("n_init", 2, std::uint64_t{1} << 30, "an initial N ≥ 2")) {
    if (doubling && !std::has_single_bit(*n)) {
      r.fail("n_init",
             fmt::format("expected a power of two (N is doubled from it and the nets need "
                         "N = 2^m), got {}; nearest {} and {}",
                         *n, std::bit_floor(*n), std::bit_ceil(*n)));
    }
    if (net_rule && *n < 256) {
      r.fail("n_init", fmt::format("expected n_init ≥ 256 for the guaranteed rule (QMCPy's "
                                   "smallest: S̃ needs enough coefficients), got {}",
                                   *n));
    }
    c.replicates.n_init = *n;
    c.guaranteed.n_init = *n;
    c.two_stage.n_init = *n;
  }
  if (auto R = r.count("replications", 2, 1U << 16, "R, between 2 and 65536")) {
    c.replicates.replications = *R;
  }
  if (auto a = r.number("alpha", "an uncertainty 0 < alpha < 1")) {
    if (!(*a > 0.0 && *a < 1.0)) {
      r.fail("alpha", fmt::format("expected an uncertainty 0 < alpha < 1, got {}", *a));
    }
    c.replicates.alpha = *a;
    c.two_stage.alpha = *a;
  }
  if (auto f = r.number("inflate", "an inflation factor ≥ 1")) {
    if (!(*f >= 1.0 && std::isfinite(*f))) {
      r.fail("inflate", fmt::format("expected an inflation factor ≥ 1, got {}", *f));
    }
    c.replicates.inflate = *f;
    c.two_stage.inflate = *f;
  }
  if (auto f = r.number("fudge", "a constant > 0")) {
    if (!(*f > 0.0 && std::isfinite(*f))) {
      r.fail("fudge", fmt::format("expected a constant > 0, got {}", *f));
    }
    c.guaranteed.fudge = *f;
  }
  if (auto lag = r.count("r_lag", 1, 20, "an integer 1 … 20")) {
    c.guaranteed.r_lag = static_cast<unsigned>(*lag);
    if (c.guaranteed.n_init < (std::uint64_t{2} << *lag)) {
      r.fail("r_lag", fmt::format("expected 2^(r_lag + 1) ≤ n_init = {}, got r_lag = {}",
                                  c.guaranteed.n_init, *lag));
    }
  }
  return c;
}

namespace {

// The budget per replicate of the replicate rule, and the most the guaranteed net rules keep.
std::uint64_t replicate_cap(const stopping_choice& c, const point_set_entry& set,
                            const point_set_options& o, std::uint64_t budget) {
  const std::uint64_t per = budget / c.replicates.replications;
  const std::uint64_t most = std::min(per, max_point_count(set, o));
  return most == 0 ? 0 : std::bit_floor(most);
}
std::uint64_t guaranteed_cap(const point_set_entry& set, const point_set_options& o,
                             std::uint64_t budget) {
  const std::uint64_t most = std::min({budget, max_point_count(set, o), guaranteed_max_values});
  return most == 0 ? 0 : std::bit_floor(most);
}

bool net_rule(const stopping_choice& c, const point_set_entry& set) {
  return *c.rule == stopping_rule::guaranteed && set.coefficients != coefficient_transform::none;
}

// The smallest count ≥ n the set holds in s dimensions (k^s for jittered points), or the largest
// ≤ `left` when that one does not fit.
std::uint64_t count_at_least(const point_set_entry& set, const point_set_options& o,
                             std::uint64_t n, std::uint64_t left, std::size_t s) {
  const point_count counts = set.counts_with(o);
  for (std::uint64_t N = n; N<left; N = N> left / 2 ? left : 2 * N) {
    const std::uint64_t c = largest_point_count(counts, N, s).points;
    if (c >= n) return c;
  }
  return largest_point_count(counts, left, s).points;
}

}  // namespace

sizing stopping_sizing(const stopping_choice& c, const point_set_entry& set,
                       const point_set_options& o, std::uint64_t budget, std::size_t) {
  if (!c.rule) return {std::nullopt, c.why_none};
  std::uint64_t first_stage = 0;
  std::uint64_t reachable = 0;
  std::string what;
  if (*c.rule == stopping_rule::replicates) {
    first_stage = c.replicates.n_init;
    reachable = replicate_cap(c, set, o, budget);
    what = fmt::format("the replicate rule's R·n_init = {}·{} evaluations",
                       c.replicates.replications, c.replicates.n_init);
  } else if (net_rule(c, set)) {
    first_stage = c.guaranteed.n_init;
    reachable = guaranteed_cap(set, o, budget);
    what = fmt::format("the guaranteed rule's n_init = {} evaluations", c.guaranteed.n_init);
  } else {
    first_stage = 2 * c.two_stage.n_init;
    reachable = budget;
    what = fmt::format("a pilot and a final sample of n_init = {} each", c.two_stage.n_init);
  }
  if (reachable < first_stage) {
    return {std::nullopt, fmt::format("the budget of {} evaluations per repetition cannot hold {}",
                                      budget, what)};
  }
  return {cell_size{budget, 0, 0, 0}, {}};
}

bool stopping_shares_chunks(const stopping_choice& c, const point_set_entry& set) {
  return c.rule && *c.rule != stopping_rule::replicates && !net_rule(c, set) &&
         sample_mean_shares_chunks;
}

repetition_result run_stopping(const stopping_choice& c, const point_set_entry& set,
                               const point_set_options& o, const method_cell& cell,
                               const run_context& context) {
  if (!c.rule) throw invalid_argument("control", "tolerance", c.why_none);
  const std::uint64_t budget = cell.size.evaluations;
  const std::size_t s = cell.function.dimension();
  stopped_estimate e;
  if (*c.rule == stopping_rule::replicates || net_rule(c, set)) {
    const bool replicates = *c.rule == stopping_rule::replicates;
    const std::uint64_t cap =
        replicates ? replicate_cap(c, set, o, budget) : guaranteed_cap(set, o, budget);
    // Replicate r draws from its own stream; the guaranteed rule's one set from the cell's.
    const auto values = [&](std::uint64_t r, std::uint64_t first, std::span<double> y) {
      const std::uint64_t stream = replicates ? stream_id({cell.stream, r}) : cell.stream;
      set.extension_values(cell.function, {context.seed, stream, context.rng}, cap, first, y,
                           context.threads, !replicates, o);
    };
    const extension_values source(values);
    if (replicates) {
      replicate_stopping_options options = c.replicates;
      options.tolerance = cell.tolerance;
      options.n_max = cap;
      e = replicate_stopping(source, options);
    } else {
      guaranteed_qmc_options options = c.guaranteed;
      options.tolerance = cell.tolerance;
      options.n_max = cap;
      e = set.coefficients == coefficient_transform::walsh ? guaranteed_digital(source, options)
                                                           : guaranteed_lattice(source, options);
    }
  } else {
    std::uint64_t spent = 0;
    const auto stage = [&](std::uint64_t which, std::uint64_t n) {
      const std::uint64_t count = count_at_least(set, o, n, budget - spent, s);
      const estimate run = set.monte_carlo(
          cell.function, {context.seed, stream_id({cell.stream, which}), context.rng}, count,
          context.threads, o);
      spent += run.evaluations;
      return stage_estimate{run.value, run.std_error, run.evaluations};
    };
    const stage_run run(stage);
    two_stage_options options = c.two_stage;
    options.tolerance = cell.tolerance;
    options.n_max = budget;
    e = *c.rule == stopping_rule::clt ? clt_stopping(run, options) : guaranteed_mc(run, options);
  }
  repetition_result out;
  out.value = e.value;
  out.evaluations = e.evaluations;
  out.error_estimate = e.claimed_error;
  return out;
}

}  // namespace quadmc::methods
