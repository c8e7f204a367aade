// Executes plan cells by method name. One switch per repetition; below it the rule and estimator
// kernels are templates over the integrand (any_integrand: one virtual call per batch).
#include "quadmc/scene/run.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/sampling_method.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/jump_error_envelope.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/romberg.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "quadmc/scene/methods.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>

namespace quadmc {

namespace {

repetition_result from_rule(const rule_result& r) {
  // A deterministic rule reports no standard error: coverage does not apply (NaN).
  return repetition_result{r.value, std::numeric_limits<double>::quiet_NaN(), r.evaluations, 0.0};
}

repetition_result from_estimate(const estimate& e) {
  return repetition_result{e.value, e.std_error, e.evaluations, 0.0};
}

repetition_result run_rule(const method_spec& m, const any_integrand& f, const plan_cell& cell,
                           unsigned threads) {
  const std::uint64_t n = cell.per_axis;
  const std::string_view name = m.name;
  const summation sum = m.accumulator;
  if (name == "left_rectangle") {
    return from_rule(integrate(f, rectangle_rule<rectangle_side::left>{}, n, threads, sum));
  }
  if (name == "right_rectangle") {
    return from_rule(integrate(f, rectangle_rule<rectangle_side::right>{}, n, threads, sum));
  }
  if (name == "midpoint") return from_rule(integrate(f, midpoint_rule{}, n, threads, sum));
  if (name == "trapezoid") return from_rule(integrate(f, trapezoid_rule{}, n, threads, sum));
  if (name == "simpson") return from_rule(integrate(f, simpson_rule{}, n, threads, sum));
  if (name == "gauss_legendre") {
    return from_rule(
        integrate(f, gauss_legendre_rule(static_cast<unsigned>(m.m)), n, threads, sum));
  }
  if (name == "romberg") {
    // The plan chose n = 2^k panels: run exactly k halvings (tolerance 0 disables early stop).
    require(std::has_single_bit(n), "romberg panels", n, "a power of two");
    romberg_options options;
    options.relative_tolerance = 0.0;
    const auto levels = static_cast<unsigned>(std::countr_zero(n));
    options.min_levels = levels;
    options.max_levels = levels;
    return from_rule(romberg(f, options));
  }
  throw invalid_argument("method", std::string(name), "a deterministic rule of methods.hpp");
}

// The a-priori bound on this rule cell's |error| when the integrand has jumps it can describe
// (rules/jump_error_envelope.hpp); NaN otherwise, and the series keeps its slope verdict.
double rule_error_envelope(const method_spec& m, const integrand_info& info,
                           const plan_cell& cell) {
  const std::uint64_t n = cell.per_axis;
  const std::string_view name = m.name;
  std::optional<double> envelope;
  if (name == "left_rectangle") {
    envelope = jump_error_envelope(rectangle_rule<rectangle_side::left>{}, info, n);
  } else if (name == "right_rectangle") {
    envelope = jump_error_envelope(rectangle_rule<rectangle_side::right>{}, info, n);
  } else if (name == "midpoint") {
    envelope = jump_error_envelope(midpoint_rule{}, info, n);
  } else if (name == "trapezoid") {
    envelope = jump_error_envelope(trapezoid_rule{}, info, n);
  } else if (name == "simpson") {
    envelope = jump_error_envelope(simpson_rule{}, info, n);
  } else if (name == "gauss_legendre") {
    envelope = jump_error_envelope(gauss_legendre_rule(static_cast<unsigned>(m.m)), info, n);
  } else if (name == "romberg" && std::has_single_bit(n)) {
    envelope = romberg_jump_error_envelope(info, static_cast<unsigned>(std::countr_zero(n)));
  }
  return envelope.value_or(std::numeric_limits<double>::quiet_NaN());
}

point_set_kind point_set_of(const method_spec& m) {
  const std::string_view name = m.name;
  // importance and the irradiance estimators draw their u from a chosen pattern; every other
  // random method is named after its point set (sampling_method.hpp owns the name table, and
  // reads "plain" as independent points).
  if (name == "importance" || name.starts_with("irradiance_")) {
    return m.point_set.empty() ? point_set_kind::independent : parse_point_set_kind(m.point_set);
  }
  return parse_point_set_kind(name == "plain_mc" ? "plain" : name);
}

repetition_result run_random(const method_spec& m, const plan& p, const plan_cell& cell,
                             std::uint64_t stream, unsigned threads) {
  const plan_instance& inst = p.instance_of(cell);
  const std::uint64_t seed = p.source.seed;
  const std::uint64_t n = cell.evaluations;
  const std::string_view name = m.name;
  const point_set_kind points = point_set_of(m);
  if (name == "importance") {
    const unit_warp_kind warp =
        m.warp == "power" ? unit_warp_kind::power : unit_warp_kind::truncated_exponential;
    return from_estimate(
        run_importance(points, inst.function, warp, m.warp_parameter, seed, stream, n, threads));
  }
  if (name.starts_with("irradiance_")) {
    const irradiance_setup setup = make_irradiance_setup(inst.params);
    const irradiance_sampling technique =
        name == "irradiance_hemisphere_uniform"  ? irradiance_sampling::uniform_hemisphere
        : name == "irradiance_hemisphere_cosine" ? irradiance_sampling::cosine_hemisphere
                                                 : irradiance_sampling::light_area;
    return from_estimate(run_irradiance(technique, points, setup, seed, stream, n, threads));
  }
  return from_estimate(run_monte_carlo(points, inst.function, seed, stream, n, threads));
}

}  // namespace

run_output run_plan(const plan& p, const run_options& options) {
  using clock = std::chrono::steady_clock;
  const auto run_start = clock::now();
  run_output out;
  out.threads_allowed = resolve_threads(options.threads.value_or(p.source.threads));
  parallel_reduce_peak_threads() = 0;

  // One series per (integrand, method), in order of first appearance (the plan's order).
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> series_index;
  // For ensembles: Ī per integrand, the mean of its instances' references (make_plan computed
  // and checked it).
  const std::vector<double>& mean_reference = p.mean_reference;
  require(mean_reference.size() == p.source.integrands.size(), "plan.mean_reference",
          mean_reference.size(), "one reference per integrand (a plan from make_plan)");

  run_progress progress;
  progress.cells_total = p.cells.size();
  progress.evaluations_total = p.total_evaluations;
  const std::optional<double> max_seconds = p.source.budget.max_seconds;

  for (const plan_cell& cell : p.cells) {
    const integrand_spec& ispec = p.source.integrands[cell.integrand];
    const method_spec& mspec = p.source.methods[cell.method];
    const double elapsed = std::chrono::duration<double>(clock::now() - run_start).count();
    if (max_seconds && elapsed > *max_seconds) {
      out.skips.push_back(
          plan_skip{fmt::format("{} × {}, N = {}", mspec.label, ispec.name, cell.nominal_N),
                    fmt::format("budget.max_seconds = {} s spent ({:.1f} s elapsed)", *max_seconds,
                                elapsed)});
      continue;
    }
    const plan_instance& inst = p.instance_of(cell);
    const integrand_info& info = inst.function.info();
    const double shift = mean_reference[cell.integrand] - info.exact;

    auto [it, inserted] =
        series_index.try_emplace({cell.integrand, cell.method}, out.series.size());
    if (inserted) {
      convergence_series series;
      series.integrand = ispec.name;
      series.s = cell.dimension;
      series.method = mspec.label;
      series.method_name = mspec.name;
      series.order = cell.order;
      series.singularity_exponent = info.singularity_exponent;
      series.smoothness = to_string(info.regularity);
      series.reference = mean_reference[cell.integrand];
      out.series.push_back(std::move(series));
    }
    // Cells come in (integrand, instance, method, N) order, so the instances of an ensemble
    // revisit the same N ladder: find the series' cell for this N, append only a new N.
    convergence_series& series = out.series[it->second];
    auto same_n = std::find_if(series.cells.begin(), series.cells.end(),
                               [&](const convergence_cell& c) { return c.n == cell.nominal_N; });
    const method_info* method = find_method(mspec.name);
    require(method != nullptr, "method", mspec.name, "a name listed by `quadmc list`");
    const bool rule = method->kind == method_kind::deterministic_rule;
    const double envelope =
        rule ? rule_error_envelope(mspec, info, cell) : std::numeric_limits<double>::quiet_NaN();
    if (same_n == series.cells.end()) {
      convergence_cell fresh;
      fresh.n = cell.nominal_N;
      fresh.per_axis = cell.per_axis;
      fresh.error_envelope = envelope;
      series.cells.push_back(std::move(fresh));
      same_n = std::prev(series.cells.end());
    } else {
      // Another instance of an ensemble: the cell's errors are the instances', so its bound is
      // the largest of theirs; NaN (no bound) as soon as one instance has none (std::max keeps a
      // NaN first argument).
      same_n->error_envelope =
          std::isnan(envelope) ? envelope : std::max(same_n->error_envelope, envelope);
    }
    convergence_cell& target = *same_n;

    for (std::uint64_t r = 0; r < cell.repetitions; ++r) {
      const auto& sp = cell.stream_parts;
      const std::uint64_t stream = stream_id({sp[0], sp[1], sp[2], sp[3], r});
      // Which cell failed, for every error a repetition can raise: the integrand (and its
      // instance), the method, N and the repetition; the cause after it names the point.
      auto where = [&] {
        std::string name = ispec.name;
        if (ispec.ensemble > 1) name += fmt::format(" instance {}", cell.instance + 1);
        return fmt::format("{} × {}, N = {} ({} evaluations), repetition {} of {}", mspec.label,
                           name, cell.nominal_N, cell.evaluations, r + 1, cell.repetitions);
      };
      const auto t0 = clock::now();
      repetition_result result;
      try {
        result = rule ? run_rule(mspec, inst.function, cell, out.threads_allowed)
                      : run_random(mspec, p, cell, stream, out.threads_allowed);
      } catch (const std::exception& e) {
        throw run_error(fmt::format("{}: {}", where(), e.what()));
      }
      result.seconds = std::chrono::duration<double>(clock::now() - t0).count();
      // Values that are each finite can still sum to inf (and Neumaier's correction to
      // inf − inf = NaN); the analysis refuses such an estimate, so it is reported here, where
      // the cell is known.
      if (!std::isfinite(result.value)) {
        throw run_error(
            fmt::format("{}: the estimate is {}: the sum of its values (f·volume, or "
                        "f/p for importance sampling) overflowed double",
                        where(), result.value));
      }
      if (!std::isnan(result.std_error) && !std::isfinite(result.std_error)) {
        throw run_error(
            fmt::format("{}: the estimate's standard error is {} (the squared "
                        "deviations of its values overflow double)",
                        where(), result.std_error));
      }
      result.value += shift;
      target.repetitions.push_back(result);
      // Reported per repetition, so a cell of 2^32 evaluations × 4 moves the bar while it runs.
      progress.evaluations_done += cell.evaluations;
      if (options.on_progress && r + 1 < cell.repetitions) options.on_progress(progress);
    }
    ++progress.cells_done;
    if (options.on_progress) options.on_progress(progress);
  }
  out.seconds = std::chrono::duration<double>(clock::now() - run_start).count();
  // A rule evaluated inline (one chunk, or a path without parallel_reduce) used this thread.
  out.threads = std::max(1u, parallel_reduce_peak_threads());
  return out;
}

}  // namespace quadmc
