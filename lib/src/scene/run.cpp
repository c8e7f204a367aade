// Executes plan cells: each repetition is one call of the cell's configured method
// (methods/method.hpp); below it the rule and estimator kernels are templates over the integrand
// (any_integrand: one virtual call per batch).
//
// Running a cell (run_cell_repetitions) and filing its repetitions into series (run_assembly)
// are apart, so that a distributed run can run cells anywhere and file them in plan order on
// one process: the series then do not depend on where a cell ran.
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

using clock = std::chrono::steady_clock;

double seconds_since(clock::time_point start) {
  return std::chrono::duration<double>(clock::now() - start).count();
}

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
    const auto t0 = clock::now();
    for (std::uint64_t i = 0; i < k; ++i) call();
    const double dt = seconds_since(t0);
    samples.push_back(dt / static_cast<double>(k));
    estimates += k;
    total += dt;
    k = batch_size(samples.back());
  }
  return summarise_timing(samples, estimates);
}

// What repetition r of `cell` runs: its absolute target and its stream. A relative tolerance is
// a fraction of this instance's |I|, exact or the reference that replaces it (the plan refused
// I = 0 or a non-finite I for it).
double absolute_tolerance(const plan& p, const plan_cell& cell, const plan_instance& inst) {
  const method_spec& mspec = p.source.methods[cell.method];
  return mspec.relative_tolerance ? cell.tolerance * std::abs(p.reference_of(inst))
                                  : cell.tolerance;
}

std::uint64_t repetition_stream(const plan_cell& cell, std::uint64_t r) {
  const auto& sp = cell.stream_parts;
  return stream_id({sp[0], sp[1], sp[2], sp[3], r});
}

// Which cell failed, for every error a repetition can raise: the integrand (and its instance),
// the method, N and the repetition; the cause after it names the point.
std::string cell_description(const plan& p, const plan_cell& cell, std::uint64_t r) {
  const integrand_spec& ispec = p.source.integrands[cell.integrand];
  std::string name = ispec.name;
  if (ispec.ensemble > 1) name += fmt::format(" instance {}", cell.instance + 1);
  const std::string target =
      !std::isnan(cell.tolerance)
          ? fmt::format("tolerance = {}", cell.tolerance)
          : fmt::format("N = {} ({} evaluations)", cell.nominal_N, cell.evaluations);
  return fmt::format("{} × {}, {}, repetition {} of {}", p.source.methods[cell.method].label, name,
                     target, r + 1, cell.repetitions);
}

}  // namespace

double resolved_timing_min_seconds(const plan& p, const run_options& options) {
  const double seconds = options.timing_min_seconds.value_or(p.source.budget.timing_min_seconds);
  require(std::isfinite(seconds) && seconds >= 0.0, "timing_min_seconds", seconds,
          "a finite number of seconds >= 0");
  return seconds;
}

cell_run run_cell_repetitions(const plan& p, std::size_t index, std::uint64_t first,
                              std::uint64_t last, const run_context& context,
                              double timing_min_seconds,
                              const std::function<void(const repetition_result&)>& on_done) {
  require(index < p.cells.size(), "cell index", index,
          fmt::format("a cell of the plan (it has {})", p.cells.size()));
  const plan_cell& cell = p.cells[index];
  require(first <= last && last <= cell.repetitions, "repetition range",
          fmt::format("[{}, {})", first, last),
          fmt::format("a range within the cell's {} repetitions", cell.repetitions));
  const integrand_spec& ispec = p.source.integrands[cell.integrand];
  const method_spec& mspec = p.source.methods[cell.method];
  const plan_instance& inst = p.instance_of(cell);
  const integrand_info& info = inst.function.info();
  require(p.mean_reference.size() == p.source.integrands.size(), "plan.mean_reference",
          p.mean_reference.size(), "one reference per integrand (a plan from make_plan)");
  // An ensemble's instances are shifted onto their mean; a given or computed reference (one
  // instance) shifts nothing: the errors are the raw estimates' distances from it.
  const double shift = ispec.reference == reference_source::exact
                           ? p.mean_reference[cell.integrand] - info.exact
                           : 0.0;
  const bool to_tolerance = !std::isnan(cell.tolerance);
  const cell_size size = cell.size();
  const double tolerance = absolute_tolerance(p, cell, inst);

  cell_run out;
  std::vector<repetition_result>& results = out.repetitions;
  results.reserve(last - first);
  for (std::uint64_t r = first; r < last; ++r) {
    const std::uint64_t stream = repetition_stream(cell, r);
    auto where = [&] { return cell_description(p, cell, r); };
    const auto t0 = clock::now();
    repetition_result result;
    try {
      const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream, r};
      result = mspec.configured->run(work, context);
    } catch (const std::exception& e) {
      throw run_error(fmt::format("{}: {}", where(), e.what()));
    }
    result.seconds = seconds_since(t0);
    if (to_tolerance) result.target = tolerance;
    // The points' measures (O(N²) discrepancies) on an ensemble's first instance only: the
    // later instances' points are more randomizations of the same set, and measuring all of
    // them cost the samplers scene more than its integrals.
    try {
      const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream, r};
      if (cell.instance == 0) mspec.configured->measure_points(work, context, result);
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
    results.push_back(result);
    // Stable timing, apart from the statistics: repetition 1's call again (run.hpp), on the
    // first instance of an ensemble (cells come in instance order, so it is the first seen).
    if (r == 0 && cell.instance == 0) {
      const method_cell work{inst.function, inst.params, size, cell.control, tolerance, stream, r};
      try {
        out.timing = time_cell([&] { (void)mspec.configured->run(work, context); }, result.seconds,
                               timing_min_seconds);
      } catch (const std::exception& e) {
        throw run_error(fmt::format("{}: {} (while timing)", where(), e.what()));
      }
    }
    if (on_done) on_done(result);
  }
  return out;
}

cell_timing time_cell_estimate(const plan& p, std::size_t index, const run_context& context,
                               double timing_min_seconds) {
  require(index < p.cells.size(), "cell index", index,
          fmt::format("a cell of the plan (it has {})", p.cells.size()));
  require(std::isfinite(timing_min_seconds) && timing_min_seconds >= 0.0, "timing_min_seconds",
          timing_min_seconds, "a finite number of seconds >= 0");
  const plan_cell& cell = p.cells[index];
  const plan_instance& inst = p.instance_of(cell);
  const cell_size size = cell.size();
  const method_spec& mspec = p.source.methods[cell.method];
  // Repetition 1's work, as run_cell_repetitions times it: the first call stands for the
  // repetition's own, which the runner's timing starts from.
  const method_cell work{inst.function,
                         inst.params,
                         size,
                         cell.control,
                         absolute_tolerance(p, cell, inst),
                         repetition_stream(cell, 0),
                         0};
  try {
    const auto t0 = clock::now();
    (void)mspec.configured->run(work, context);
    const double first = seconds_since(t0);
    return time_cell([&] { (void)mspec.configured->run(work, context); }, first,
                     timing_min_seconds);
  } catch (const std::exception& e) {
    throw run_error(fmt::format("{}: {} (while timing)", cell_description(p, cell, 0), e.what()));
  }
}

run_assembly::run_assembly(const plan& p) : plan_(&p) {}

void run_assembly::add(std::size_t index, cell_run run) {
  std::vector<repetition_result>& repetitions = run.repetitions;
  const plan& p = *plan_;
  require(index < p.cells.size(), "cell index", index,
          fmt::format("a cell of the plan (it has {})", p.cells.size()));
  require(added_ == 0 || index > last_added_, "cell index", index,
          fmt::format("a cell after cell {} (cells are filed in plan order)", last_added_));
  const plan_cell& cell = p.cells[index];
  require(repetitions.size() == cell.repetitions, "repetitions of the cell", repetitions.size(),
          fmt::format("the cell's {} repetitions", cell.repetitions));
  added_ += 1;
  last_added_ = index;
  const integrand_spec& ispec = p.source.integrands[cell.integrand];
  const method_spec& mspec = p.source.methods[cell.method];
  const plan_instance& inst = p.instance_of(cell);
  const integrand_info& info = inst.function.info();

  // One series per (integrand, method), in order of first appearance (the plan's order).
  auto [it, inserted] =
      series_index_.try_emplace({cell.integrand, cell.method}, output_.series.size());
  if (inserted) {
    convergence_series series;
    series.integrand = ispec.name;
    series.s = cell.dimension;
    series.method = mspec.label;
    series.regularity = info.regularity;
    series.theory = mspec.configured->theory(integrand_class{
        info.regularity, cell.dimension, info.singularity_exponent,
        info.regularity == smoothness::discontinuous && !info.separable_factors.empty()});
    series.reference = p.mean_reference[cell.integrand];
    if (cell.integrand < p.references.size()) {
      series.reference_uncertainty = p.references[cell.integrand].uncertainty;
    }
    series.relative_tolerance = mspec.relative_tolerance;
    // A cell run to a tolerance claims its own error (the stopping rule's, over its own
    // replicates where it has them), whatever a fixed-size cell of the method would need.
    series.errors =
        cell.control == cell_control::tolerance ? error_bars::own : mspec.configured->error_bars();
    series.rounding = rounding_model{info.precision, mspec.configured->summation_scheme()};
    // A prediction is of one instance on fixed grids: not for an ensemble (its cells pool
    // instances) nor for cells that may stop early.
    if (ispec.ensemble <= 1 && cell.control == cell_control::fixed_size) {
      series.prediction = mspec.configured->predict_error(info);
    }
    output_.series.push_back(std::move(series));
  }
  // Cells come in (integrand, instance, method, N) order, so the instances of an ensemble
  // revisit the same N ladder: find the series' cell for this N, append only a new N.
  convergence_series& series = output_.series[it->second];
  const bool to_tolerance = !std::isnan(cell.tolerance);
  auto same_n =
      std::find_if(series.cells.begin(), series.cells.end(), [&](const convergence_cell& c) {
        return to_tolerance ? c.tolerance == cell.tolerance : c.n == cell.nominal_N;
      });
  // An a-priori bound holds for a cell of fixed size; one that may stop early has none.
  const double envelope = cell.control == cell_control::fixed_size
                              ? mspec.configured->error_envelope(info, cell.size())
                              : std::numeric_limits<double>::quiet_NaN();
  if (same_n == series.cells.end()) {
    convergence_cell fresh;
    fresh.n = cell.nominal_N;
    fresh.tolerance = cell.tolerance;
    fresh.per_axis = cell.per_axis;
    fresh.error_envelope = envelope;
    fresh.timing = run.timing;
    series.cells.push_back(std::move(fresh));
    same_n = std::prev(series.cells.end());
  } else {
    // Another instance of an ensemble: the cell's errors are the instances', so its bound is
    // the largest of theirs; NaN (no bound) as soon as one instance has none (std::max keeps a
    // NaN first argument).
    same_n->error_envelope =
        std::isnan(envelope) ? envelope : std::max(same_n->error_envelope, envelope);
    same_n->instances += 1;
  }
  same_n->repetitions.insert(same_n->repetitions.end(), repetitions.begin(), repetitions.end());
}

void run_assembly::skip(plan_skip skipped) {
  output_.skips.push_back(std::move(skipped));
}

run_output run_assembly::finish() && {
  return std::move(output_);
}

}  // namespace quadmc
