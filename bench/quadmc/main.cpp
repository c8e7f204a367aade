// The `quadmc` command: run a scene, print its plan, list what scenes may name, compare two
// result folders. Every failure is one line on stderr and a non-zero exit:
//   1  bad input (scene file, flags, values) or a failed run
//   1  compare found a regression (so it can gate CI); 0 when none
//   2  command-line usage errors (CLI11's own codes otherwise)
#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/report/compare.hpp"
#include "quadmc/report/results_folder.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"

#include "catalogue_listing.hpp"
#include "progress_bar.hpp"
#include "subprocess.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The SIMD level is part of what fixes the last bits of exp/cos (core/simd_level.hpp), so the
// results page names it beside the thread count.
std::string machine_description() {
  return fmt::format("{} hardware threads, SIMD level {} (QUADMC_SIMD to choose)",
                     std::thread::hardware_concurrency(),
                     quadmc::to_string(quadmc::active_simd_level()));
}

// The folder a run writes, absolute and without a trailing separator: with "out/" filename() is
// empty, so the staging folder "out/.partial" would land inside the target and be deleted with it;
// with "." the target would be the working directory itself. Checked before the run, so a refusal
// costs nothing: an existing folder is replaced only when it holds nothing but files a run writes
// (CSV, README.md, SVG plots), so `--out .` or `--out ~` is an error, not a deleted folder.
fs::path results_folder(const std::string& out_dir, const std::string& scene_name) {
  const fs::path given = out_dir.empty() ? fs::path("results") / scene_name : fs::path(out_dir);
  fs::path folder = fs::absolute(given).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();  // "/a/out/" → "/a/out"
  if (!folder.has_filename() || folder == folder.root_path()) {
    throw quadmc::invalid_argument("--out", given.string(), "a folder below the file system root");
  }
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (!fs::exists(status)) return folder;
  if (!fs::is_directory(status)) {
    throw quadmc::invalid_argument("--out", given.string(), "a folder, not a file");
  }
  for (const auto& entry : fs::directory_iterator(folder)) {
    const fs::path name = entry.path().filename();
    const bool written_by_a_run = name == "convergence.csv" || name == "slopes.csv" ||
                                  name == "README.md" || name.extension() == ".svg";
    if (!written_by_a_run) {
      throw quadmc::invalid_argument(
          "--out", given.string(),
          fmt::format("a new folder or an earlier results folder; it holds '{}', which a run does "
                      "not write, so it is not replaced",
                      name.string()));
    }
  }
  return folder;
}

// Writes the results into a fresh sibling folder and moves it into place only when everything
// (CSV, Markdown, plots) succeeded: a failed run never leaves files claiming success, and the
// staging folder is removed when a step fails.
void write_results(const quadmc::plan& p, const quadmc::run_output& out,
                   const std::vector<quadmc::convergence_table>& tables, const fs::path& folder) {
  quadmc::run_info info;
  info.scene = p.source.name;
  info.seed = p.source.seed;
  info.threads = out.threads;
  info.machine = machine_description();
  info.compiler = fmt::format("{} ({})", QUADMC_COMPILER, QUADMC_BUILD_TYPE);
  info.run_seconds = out.seconds;
  for (const auto& skip : p.skips) info.skipped.push_back(skip.what + ": " + skip.reason);
  for (const auto& skip : out.skips) info.skipped.push_back(skip.what + ": " + skip.reason);

  const fs::path staging = folder.parent_path() / (folder.filename().string() + ".partial");
  fs::remove_all(staging);
  quadmc::results_outputs outputs;
  outputs.csv = p.source.output.csv;
  outputs.markdown = p.source.output.markdown;
  try {
    quadmc::write_results_folder(staging, info, tables, outputs);
    if (p.source.output.plots) {
      const auto argv = quadmc::plot_command_line(QUADMC_PLOT_SCRIPT, staging);
      quadmc_cli::run_subprocess(argv);
    }
    fs::remove_all(folder);
    fs::rename(staging, folder);
  } catch (...) {
    std::error_code ignored;  // the first error is the one to report
    fs::remove_all(staging, ignored);
    throw;
  }
}

int run_command(const std::string& scene_file, const std::string& out_dir, unsigned threads) {
  const quadmc::scene scene = quadmc::parse_scene_file(scene_file);
  const quadmc::plan p = quadmc::make_plan(scene);
  const fs::path folder = results_folder(out_dir, scene.name);
  fmt::print("{}\n", quadmc::format_plan(p));
  std::fflush(stdout);

  quadmc_cli::progress_bar bar;
  quadmc::run_options options;
  options.threads = threads;
  options.on_progress = [&bar](const quadmc::run_progress& progress) { bar.update(progress); };
  const quadmc::run_output out = quadmc::run_plan(p, options);
  bar.finish();

  std::vector<quadmc::convergence_table> tables;
  tables.reserve(out.series.size());
  for (const auto& series : out.series) tables.push_back(quadmc::analyse_convergence(series));

  write_results(p, out, tables, folder);
  fmt::print("{}\n", quadmc_cli::slope_summary(tables));
  fmt::print("ran {} cells in {:.1f} s on {} threads; wrote {}\n", p.cells.size(), out.seconds,
             out.threads, folder.string());
  return 0;
}

int plan_command(const std::string& scene_file) {
  const quadmc::plan p = quadmc::make_plan(quadmc::parse_scene_file(scene_file));
  fmt::print("{}\n", quadmc::format_plan(p));
  return 0;
}

int compare_command(const std::string& a, const std::string& b, double tolerance) {
  const quadmc::compare_result result = quadmc::compare_results(a, b, tolerance);
  fmt::print("{}\n", quadmc::render_compare_markdown(result));
  return result.regression ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"quadmc: convergence of quadrature rules against Monte Carlo"};
  app.require_subcommand(1);

  std::string scene_file;
  std::string out_dir;
  unsigned threads = 0;
  auto* run =
      app.add_subcommand("run", "Run a scene and write results/<name>/ (CSV, Markdown, plots)");
  run->add_option("scene", scene_file, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "Output folder (default: results/<scene name>)");
  run->add_option("--threads", threads, "Threads (default: the scene's; 0 = all cores)");

  auto* plan = app.add_subcommand("plan", "Print the cells a scene would run and what it skips");
  plan->add_option("scene", scene_file, "Scene file (TOML)")->required()->check(CLI::ExistingFile);

  auto* list = app.add_subcommand("list", "List integrands, methods, point sets and warps");

  std::string folder_a;
  std::string folder_b;
  double tolerance = 0.1;
  auto* compare = app.add_subcommand(
      "compare", "Compare two results folders; exit 1 when a slope regresses (see README)");
  compare->add_option("baseline", folder_a, "Results folder A (baseline)")->required();
  compare->add_option("candidate", folder_b, "Results folder B (candidate)")->required();
  compare->add_option("--tolerance", tolerance,
                      "Slope regression tolerance (default 0.1; see README)");

  CLI11_PARSE(app, argc, argv);
  try {
    // A bad QUADMC_SIMD is reported before any work, not from inside the first batch.
    (void)quadmc::active_simd_level();
    if (*run) return run_command(scene_file, out_dir, threads);
    if (*plan) return plan_command(scene_file);
    if (*list) {
      fmt::print("{}", quadmc_cli::catalogue_listing());
      return 0;
    }
    if (*compare) return compare_command(folder_a, folder_b, tolerance);
  } catch (const std::exception& e) {
    // One line: the library's messages are single lines naming file, line, key or parameter.
    fmt::print(stderr, "quadmc: {}\n", e.what());
    return 1;
  }
  return 2;
}
