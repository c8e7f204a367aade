// Executes plan cells: each repetition is one call of the cell's configured method
// (methods/method.hpp); below it the rule and estimator kernels are templates over the integrand
// (any_integrand: one virtual call per batch).
#include "quadmc/scene/run.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace quadmc {
namespace {

using timing_clock = std::chrono::steady_clock;

// Stable timing of one cell (the procedure in run.hpp): `call` runs one estimate, `first` is the
// time repetition 1 took. Batches aim at a tenth of the minimum each, so the median is of ~10
// samples; k is re-aimed after every batch from the last one's time per estimate.
template <class Call>
cell_timing time_cell(Call&& call, double first, double min_seconds) {
  if (first >= min_seconds) {
    const double once[] = {first};
    return summarise_timing(once, 1);
  }
  const double batch_target = min_seconds / 10.0;
  // A call below 10 ns is below what the clock resolves; 2^20 calls per batch at most.
  constexpr double floor_seconds = 1e-8;
  constexpr std::uint64_t max_batch = std::uint64_t{1} << 20;
  auto batch_size = [&](double per_estimate) {
    const double k = std::floor(batch_target / std::max(per_estimate, floor_seconds));
    return static_cast<std::uint64_t>(std::clamp(k, 1.0, static_cast<double>(max_batch)));
  };
  std::uint64_t k = batch_size(first);
  std::vector<double> samples;
  std::uint64_t estimates = 0;
  double total = 0.0;
  while (total < min_seconds || samples.size() < 2) {
    const auto t0 = timing_clock::now();
    for (std::uint64_t i = 0; i < k; ++i) call();
    const double dt = std::chrono::duration<double>(timing_clock::now() - t0).count();
    samples.push_back(dt / static_cast<double>(k));
    estimates += k;
    total += dt;
    k = batch_size(samples.back());
  }
  return summarise_timing(samples, estimates);
}

}  // namespace

run_output run_plan(const plan& p, const run_options& options) {
  using clock = std::chrono::steady_clock;
  const auto run_start = clock::now();
  run_output out;
  out.threads_allowed = resolve_threads(options.threads.value_or(p.source.threads));
  const double timing_min_seconds =
      options.timing_min_seconds.value_or(p.source.budget.timing_min_seconds);
  require(std::isfinite(timing_min_seconds) && timing_min_seconds >= 0.0, "timing_min_seconds",
          timing_min_seconds, "a finite number of seconds >= 0");
  const run_context context{p.source.seed, out.threads_allowed};
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
      series.regularity = info.regularity;
      series.theory = mspec.configured->theory(
          integrand_class{info.regularity, cell.dimension, info.singularity_exponent});
      series.reference = mean_reference[cell.integrand];
      series.relative_tolerance = mspec.relative_tolerance;
      series.errors = mspec.configured->error_bars();
      series.rounding = rounding_model{info.precision, mspec.configured->summation_scheme()};
      // A prediction is of one instance on fixed grids: not for an ensemble (its cells pool
      // instances) nor for cells that may stop early.
      if (ispec.ensemble <= 1 && cell.control == cell_control::fixed_size) {
        series.prediction = mspec.configured->predict_error(info);
      }
      out.series.push_back(std::move(series));
    }
    // Cells come in (integrand, instance, method, N) order, so the instances of an ensemble
    // revisit the same N ladder: find the series' cell for this N, append only a new N.
    convergence_series& series = out.series[it->second];
    const bool to_tolerance = !std::isnan(cell.tolerance);
    auto same_n =
        std::find_if(series.cells.begin(), series.cells.end(), [&](const convergence_cell& c) {
          return to_tolerance ? c.tolerance == cell.tolerance : c.n == cell.nominal_N;
        });
    const cell_size size = cell.size();
    // An a-priori bound holds for a cell of fixed size; one that may stop early has none.
    const double envelope = cell.control == cell_control::fixed_size
                                ? mspec.configured->error_envelope(info, size)
                                : std::numeric_limits<double>::quiet_NaN();
    const bool first_instance = same_n == series.cells.end();
    if (first_instance) {
      convergence_cell fresh;
      fresh.n = cell.nominal_N;
      fresh.tolerance = cell.tolerance;
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

    // The absolute target: a relative tolerance is a fraction of this instance's |I| (the plan
    // refused I = 0 or a non-finite I for it).
    const double tolerance =
        mspec.relative_tolerance ? cell.tolerance * std::abs(info.exact) : cell.tolerance;
    for (std::uint64_t r = 0; r < cell.repetitions; ++r) {
      const auto& sp = cell.stream_parts;
      const std::uint64_t stream = stream_id({sp[0], sp[1], sp[2], sp[3], r});
      // Which cell failed, for every error a repetition can raise: the integrand (and its
      // instance), the method, N and the repetition; the cause after it names the point.
      auto where = [&] {
        std::string name = ispec.name;
        if (ispec.ensemble > 1) name += fmt::format(" instance {}", cell.instance + 1);
        const std::string target =
            to_tolerance ? fmt::format("tolerance = {}", cell.tolerance)
                         : fmt::format("N = {} ({} evaluations)", cell.nominal_N, cell.evaluations);
        return fmt::format("{} × {}, {}, repetition {} of {}", mspec.label, name, target, r + 1,
                           cell.repetitions);
      };
      const auto t0 = clock::now();
      repetition_result result;
      try {
        const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream};
        result = mspec.configured->run(work, context);
      } catch (const std::exception& e) {
        throw run_error(fmt::format("{}: {}", where(), e.what()));
      }
      result.seconds = std::chrono::duration<double>(clock::now() - t0).count();
      try {
        const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream};
        mspec.configured->measure_points(work, context, result);
      } catch (const std::exception& e) {
        throw run_error(fmt::format("{}: {}", where(), e.what()));
      }
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
      if (r == 0 && first_instance) {
        // Stable timing, apart from the statistics: repetition 1's call again (run.hpp).
        const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream};
        try {
          target.timing = time_cell([&] { (void)mspec.configured->run(work, context); },
                                    result.seconds, timing_min_seconds);
        } catch (const std::exception& e) {
          throw run_error(fmt::format("{}: {} (while timing)", where(), e.what()));
        }
      }
      // Reported per repetition, so a cell of 2^32 evaluations × 4 moves the bar while it runs.
      progress.evaluations_done += result.evaluations;
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
