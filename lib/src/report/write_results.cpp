// A scene's results folder (report/write_results.hpp).
#include "quadmc/report/write_results.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/report/answer_first.hpp"
#include "quadmc/report/markdown_report.hpp"
#include "quadmc/report/results_folder.hpp"
#include "quadmc/report/time_to_error_table.hpp"
#include "quadmc/report/who_leads.hpp"
#include "quadmc/scene/paired_timing.hpp"

#include <fmt/format.h>

#include <set>
#include <thread>
#include <utility>

namespace quadmc {

namespace {

bool draws_plots(const plan& p, const results_options& options) {
  return p.source.output.plots && !options.plot_script.empty();
}

// The SIMD level is part of what fixes the last bits of exp/cos (core/simd_level.hpp), so the
// results page names it beside the thread count.
std::string machine_description() {
  return fmt::format("{} hardware threads, SIMD level {} (QUADMC_SIMD to choose)",
                     std::thread::hardware_concurrency(), to_string(active_simd_level()));
}

run_info info_of(const scene_results& results, const results_options& options) {
  const plan& p = results.plan;
  run_info info;
  info.scene = p.source.name;
  info.description = p.source.description;
  info.seed = p.source.seed;
  info.threads = results.run.threads;
  info.threads_allowed = results.run.threads_allowed;
  info.ranks = options.ranks;
  info.machine = machine_description();
  info.build = options.build;
  info.build.rng = std::string(to_string(p.source.rng));
  info.run_seconds = results.run.seconds;
  for (const auto& skip : p.skips) info.skipped.push_back(skip.what + ": " + skip.reason);
  for (const auto& skip : results.run.skips) info.skipped.push_back(skip.what + ": " + skip.reason);
  for (std::size_t fi = 0; fi < p.references.size(); ++fi) {
    const plan_reference& ref = p.references[fi];
    if (ref.source == reference_source::exact) continue;
    info.references.push_back(fmt::format("{}: reference = {:.17g} ± {:.2g} ({})",
                                          p.source.integrands[fi].name, ref.value, ref.uncertainty,
                                          ref.describe()));
  }
  for (const plan_instance& inst : p.instances) {
    if (inst.instance != 0) continue;
    const integrand_spec& spec = p.source.integrands[inst.integrand];
    const integrand_info& f = inst.function.info();
    effective_dimension_row row{spec.name,    f.dimension(), spec.ensemble,
                                std::nullopt, std::nullopt,  {}};
    if (f.moments) {
      row.exact = exact_effective_dimensions(*f.moments);
    } else if (f.dimension() >= 2 && p.source.output.markdown) {
      // Only the page shows it. Its own stream, named by the scene's seed and the integrand's
      // name: the same numbers whatever else the scene holds, on any thread and rank count (one
      // thread computes it). The run's results are already in memory: an integrand that throws
      // here (an outside or a Python one) costs the page this row's estimate, not the folder.
      try {
        row.estimated = estimate_effective_dimensions(
            inst.function, stream_id({p.source.seed, name_id(spec.name)}));
      } catch (const std::exception& e) {
        row.not_estimated = e.what();
      }
    }
    info.effective_dimensions.push_back(std::move(row));
  }
  info.paired_timing = results.paired_timing;
  info.csv = p.source.output.csv;
  info.plots = draws_plots(p, options);
  return info;
}

}  // namespace

bool writes_results(const plan& p, const results_options& options) {
  const output_spec& output = p.source.output;
  return output.csv || output.markdown || draws_plots(p, options);
}

std::vector<std::string> result_file_names(const plan& p, const results_options& options) {
  std::vector<std::string> files = {std::string(meta_csv_file)};
  const output_spec& output = p.source.output;
  if (output.csv) {
    files.insert(files.end(), {"convergence.csv", "slopes.csv", std::string(who_leads_csv_file)});
    // Whether the run pairs any cell only the run tells; listed when it may.
    if (may_pair_time_to_error(p.source) && p.source.budget.paired_timing_rounds > 0) {
      files.emplace_back(time_to_error_pairs_csv_file);
    }
  }
  if (output.markdown) files.emplace_back("README.md");
  if (draws_plots(p, options)) {
    std::set<std::pair<std::string, std::size_t>> groups;
    for (const plan_cell& cell : p.cells) {
      groups.emplace(p.source.integrands[cell.integrand].name, cell.dimension);
    }
    for (const auto& [integrand, s] : groups) {
      files.push_back(convergence_plot_file(integrand, s));
      files.push_back(work_precision_plot_file(integrand, s));
    }
    // The summary figures: the who-leads one is drawn only where the page has a table, which
    // the plan cannot tell; the list is for the checks of names before the run, so it may hold
    // one name more than the run writes.
    for (const std::string_view stem : {slope_figure_stem, who_leads_figure_stem}) {
      for (const char* extension : {".svg", ".png"}) {
        files.push_back(std::string(stem) + extension);
      }
    }
  }
  return files;
}

std::unique_ptr<staged_output> stage_results(const plan& p, const std::string& out,
                                             const results_options& options) {
  if (!writes_results(p, options)) return nullptr;
  const bool given = !out.empty();
  return std::make_unique<staged_output>(
      "run", given ? "--out" : "results folder",
      given ? out : (std::filesystem::path("results") / p.source.name).string(),
      results_folder_path(out, p.source.name), result_file_names(p, options));
}

std::string write_results(staged_output& staged, const scene_results& results,
                          const results_options& options, std::string* warning) {
  const output_spec& output = results.plan.source.output;
  results_outputs files;
  files.csv = output.csv;
  files.markdown = output.markdown;
  staged.write([&](const std::filesystem::path& folder) {
    write_results_folder(folder, info_of(results, options), results.tables, files);
  });
  if (draws_plots(results.plan, options)) {
    staged.run_child(plot_command_line(options.plot_script, staged.staging()));
  }
  staged_output::committed done = staged.commit();
  if (warning != nullptr) *warning = std::move(done.warning);
  return done.written;
}

std::string write_results(const std::filesystem::path& folder, const scene_results& results,
                          const results_options& options, std::string* warning) {
  const std::unique_ptr<staged_output> staged =
      stage_results(results.plan, folder.string(), options);
  if (!staged) return std::string(nothing_written);
  return write_results(*staged, results, options, warning);
}

}  // namespace quadmc
