// The `quadmc` command (quadmc/command.hpp, command_main): run a scene, print its plan, list what
// scenes may name, compare two result folders, write a point set's points (points_command.hpp),
// draw the point-set gallery (gallery_command.hpp), render the plane under the area light
// (render_command.hpp).
//
// Exit status (also in `quadmc --help`):
//   0        success; for `compare`, no slope regression
//   1        bad input (scene file, values), a failed run, a failed write (stdout included), a
//            refused results folder; for `compare`, a slope regression (so it can gate CI)
//   2        command-line usage error: unknown flag or subcommand, missing or malformed argument,
//            value out of range. One line on stderr (CLI11's own codes 104–114 and its
//            two-line message are not used); `--help` prints help on stdout and exits 0
//   3        `compare` only: the folders are incomparable (B lacks a series or a fit of A, or
//            no series is fitted in both), report/compare.hpp
//   130/143  interrupted by SIGINT/SIGTERM: the plot process killed, this run's staging folder
//            removed, the old results untouched (report/interruption.hpp)
// Every failure is one line on stderr, "quadmc: …".
//
// Environment: QUADMC_SIMD pins the SIMD level (core/simd_level.hpp). Plots are drawn by
// Debian's /usr/bin/python3 with python3-matplotlib (report/results_folder.hpp).
//
// `run` writes its folder by the rules of report/results_staging.hpp (own staging folder, lock,
// atomic replace, never deleting what it did not create), checks before computing anything what
// would make the write fail (folder name lengths, writability, a concurrent run, matplotlib when
// plots are on), and touches no folder when every [output] is off. When stdout cannot be written (a
// full disk, /dev/full, a closed pipe) the run still writes its folder, which is the product
// (stdout only repeats the plan and the summary), and then exits 1 saying so.
#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/report/compare.hpp"
#include "quadmc/report/interruption.hpp"
#include "quadmc/report/markdown_report.hpp"
#include "quadmc/report/results_folder.hpp"
#include "quadmc/report/staged_output.hpp"
#include "quadmc/report/write_results.hpp"
#include "quadmc/scene/cell_scheduler.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"
#include "quadmc/scene/run_scene.hpp"
#include "quadmc/scene/schedule.hpp"

#include "quadmc/command.hpp"

#include "build_provenance.hpp"
#include "catalogue_listing.hpp"
#include "cli_validators.hpp"
#include "gallery_command.hpp"
#include "mpi_run.hpp"
#include "plot_script.hpp"
#include "points_command.hpp"
#include "progress_bar.hpp"
#include "render_command.hpp"
#include "version.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace interruption = quadmc::interruption;

// The program's name at the start of each message line (command_options::name).
std::string program = "quadmc";

constexpr int exit_failure = 1;
constexpr int exit_usage = 2;
constexpr int exit_incomparable = 3;

constexpr std::string_view exit_status_help =
    "Exit status: 0 success (compare: no slope regression); 1 bad input, a failed run or write, "
    "or (compare) a slope regression; 2 usage error; 3 (compare) incomparable: B lacks a series "
    "or a fit of A, or no series is fitted in both; 130/143 interrupted by SIGINT/SIGTERM.\n"
    "Environment: QUADMC_SIMD=scalar|sse2|avx2|avx512 pins the SIMD level.";

// stdout is fully buffered when redirected, so a write error (a full disk, /dev/full, a closed
// pipe) shows only when the buffer is flushed: every print is flushed and checked, and the first
// error is kept for the exit status.
class standard_output {
 public:
  void print(std::string_view text) noexcept {
    if (error_ != 0) return;
    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() ||
        std::fflush(stdout) != 0) {
      error_ = errno != 0 ? errno : EIO;
    }
  }
  bool failed() const noexcept { return error_ != 0; }
  std::string message() const {
    return fmt::format("cannot write to standard output: {}", std::strerror(error_));
  }

 private:
  int error_ = 0;
};

struct run_request {
  std::string scene_file;
  std::string out_dir;
  std::optional<unsigned> threads;           // empty: the scene's
  std::optional<double> timing_min_seconds;  // empty: the scene's budget.timing_min_seconds
  std::string split_cells = "auto";          // under mpirun: which cells all ranks run together
  std::string cells_csv;                     // where to write each cell's placement; empty: none
};

std::string cells_ran_text(std::size_t ran, std::size_t planned, double seconds) {
  if (ran == planned) return fmt::format("ran {} cells in {:.1f} s", ran, seconds);
  return fmt::format("ran {} of {} cells in {:.1f} s ({} skipped by budget.max_seconds)", ran,
                     planned, seconds, planned - ran);
}

std::string threads_text(const quadmc::run_output& out, unsigned ranks) {
  const std::string per_rank = ranks > 1 ? fmt::format("{} MPI ranks × ", ranks) : "";
  if (out.threads == out.threads_allowed) {
    return fmt::format("on {}{} threads", per_rank, out.threads);
  }
  return fmt::format("on {}{} threads ({} allowed; no cell had work for more)", per_rank,
                     out.threads, out.threads_allowed);
}

// Whether `file` can be written at the end of a run without touching it now: an existing
// regular file we may write, or a new name in a folder we may write into. Throws
// quadmc::invalid_argument naming `option`.
void check_writable_file(const std::string& option, const std::string& file) {
  std::error_code ec;
  const fs::path path(file);
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_regular_file(status)) {
      throw quadmc::invalid_argument(option, file, "a file (this is a folder or a special file)");
    }
    if (::access(path.c_str(), W_OK) != 0) {
      throw quadmc::invalid_argument(option, file,
                                     fmt::format("a writable file ({})", std::strerror(errno)));
    }
    return;
  }
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) {
    throw quadmc::invalid_argument(
        option, file, fmt::format("a file in an existing folder ({} is not one)", parent.string()));
  }
  if (::access(parent.c_str(), W_OK | X_OK) != 0) {
    throw quadmc::invalid_argument(
        option, file,
        fmt::format("a file in a writable folder ({}: {})", parent.string(), std::strerror(errno)));
  }
}

quadmc::run_options run_options_of(const run_request& request) {
  quadmc::run_options options;
  options.threads = request.threads;
  options.timing_min_seconds = request.timing_min_seconds;
  return options;
}

// Under mpirun, a rank other than 0 follows rank 0: it runs its share of the cells, prints and
// writes nothing, and gives up when rank 0 refused to start (mpi_run.hpp).
int follow_rank0(const quadmc::plan& p, const quadmc::run_options& options,
                 const quadmc_cli::mpi::world& world, quadmc::split_policy split) {
  if (p.cells.empty() || !quadmc_cli::mpi::agree_to_proceed(world, true)) return exit_failure;
  quadmc_cli::mpi::mpi_scheduler scheduler(world, split);
  (void)quadmc::run_plan(p, options, scheduler);
  return 0;
}

// Everything checked before any work, so that a refusal costs nothing (found after the run, an
// unwritable --cells-csv or a missing matplotlib cost every cell's computing): the --cells-csv
// file, the results folder (staged here), the plotting stack. The other ranks learn the verdict.
std::unique_ptr<quadmc::staged_output> stage(const run_request& request, const quadmc::plan& p,
                                             const quadmc::results_options& results,
                                             const quadmc_cli::mpi::world& world) {
  std::unique_ptr<quadmc::staged_output> staged;
  try {
    if (!request.cells_csv.empty()) check_writable_file("--cells-csv", request.cells_csv);
    staged = quadmc::stage_results(p, request.out_dir, results);
    if (staged && p.source.output.plots) {
      quadmc_cli::check_plotting(results.plot_script, "or set plots = false in [output]");
    }
  } catch (...) {
    (void)quadmc_cli::mpi::agree_to_proceed(world, false);
    throw;
  }
  (void)quadmc_cli::mpi::agree_to_proceed(world, true);
  return staged;
}

// The cells' scheduler: every cell here in one process (the MPI file is then not involved), placed
// on ranks under mpirun.
class cells_scheduler {
 public:
  cells_scheduler(const quadmc_cli::mpi::world& world, quadmc::split_policy split) {
    if (world.size > 1) many_.emplace(world, split);
  }
  quadmc::cell_scheduler& get() noexcept {
    if (many_) return *many_;
    return here_;
  }
  // Where each cell ran: all on rank 0 in one process.
  std::vector<quadmc::cell_placement> placement(std::size_t cells) const {
    return many_ ? many_->placement() : std::vector<quadmc::cell_placement>(cells);
  }

 private:
  quadmc::local_scheduler here_;
  std::optional<quadmc_cli::mpi::mpi_scheduler> many_;
};

// `run --cells-csv FILE`: each cell's placement (schedule.hpp, cells_csv); nothing when empty.
void write_cells_csv(const std::string& file, const quadmc::plan& p,
                     const cells_scheduler& scheduler) {
  if (file.empty()) return;
  const std::string text = quadmc::cells_csv(p, scheduler.placement(p.cells.size()));
  std::FILE* stream = std::fopen(file.c_str(), "w");
  const bool ok =
      stream != nullptr && std::fwrite(text.data(), 1, text.size(), stream) == text.size();
  const int error = errno;
  if (stream == nullptr || std::fclose(stream) != 0 || !ok) {
    throw std::runtime_error(
        fmt::format("cannot write --cells-csv {}: {}", file, std::strerror(error)));
  }
}

int run_command(const run_request& request, standard_output& out,
                const quadmc_cli::mpi::world& world) {
  const quadmc::split_policy split = quadmc::parse_split_policy(request.split_cells);
  quadmc::run_options options = run_options_of(request);
  quadmc::plan p = quadmc::plan_scene(request.scene_file, options);
  if (world.rank != 0) return follow_rank0(p, options, world, split);
  if (p.cells.empty()) out.print(quadmc::format_plan(p) + "\n");
  quadmc::require_cells(p, request.scene_file);
  const quadmc::results_options results{quadmc::bench::build_provenance(), world.size,
                                        quadmc_cli::plot_script_path()};
  const std::unique_ptr<quadmc::staged_output> staged = stage(request, p, results, world);
  out.print(quadmc::format_plan(p) + "\n");

  quadmc_cli::progress_bar bar;
  options.on_progress = [&bar](const quadmc::run_progress& progress) {
    const auto held = interruption::hold();
    bar.update(progress);
  };
  cells_scheduler scheduler(world, split);
  const quadmc::scene_results r = quadmc::run_scene(std::move(p), options, scheduler.get());
  write_cells_csv(request.cells_csv, r.plan, scheduler);
  {
    const auto held = interruption::hold();
    bar.finish();
  }
  std::string warning;
  const std::string written = staged ? quadmc::write_results(*staged, r, results, &warning)
                                     : std::string(quadmc::nothing_written);
  out.print(quadmc_cli::slope_summary(r.tables) + "\n");
  out.print(fmt::format("{} {}; {}\n",
                        cells_ran_text(r.cells_ran(), r.plan.cells.size(), r.run.seconds),
                        threads_text(r.run, world.size), written));
  if (!warning.empty()) fmt::print(stderr, "{}: warning: {}\n", program, warning);
  if (out.failed()) {
    throw std::runtime_error(
        out.message() + (staged ? "; the run itself succeeded and " + written : std::string()));
  }
  return 0;
}

int plan_command(const std::string& scene_file, standard_output& out) {
  const quadmc::plan p = quadmc::plan_scene(scene_file);
  out.print(quadmc::format_plan(p) + "\n");
  if (out.failed()) throw std::runtime_error(out.message());
  return 0;
}

// CLI11's messages, made one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

int compare_command(const std::string& a, const std::string& b, double tolerance,
                    standard_output& out) {
  quadmc::compare_result result;
  try {
    result = quadmc::compare_results(a, b, tolerance);
  } catch (const quadmc::invalid_argument& e) {
    // A folder whose files cannot be read as results (a missing column, a malformed row) cannot
    // be compared: the same exit status as a candidate that lacks what the baseline has.
    fmt::print(stderr, "{}: compare: incomparable: {}\n", program, one_line(e.what()));
    return exit_incomparable;
  }
  out.print(quadmc::render_compare_markdown(result) + "\n");
  if (out.failed()) throw std::runtime_error(out.message());
  switch (result.outcome) {
    case quadmc::compare_outcome::no_regression:
      return 0;
    case quadmc::compare_outcome::regression:
      fmt::print(stderr, "{}: compare: {}\n", program, result.reason);
      return exit_failure;
    case quadmc::compare_outcome::incomparable:
      fmt::print(stderr, "{}: compare: incomparable: {}\n", program, result.reason);
      return exit_incomparable;
  }
  return exit_failure;
}

}  // namespace

// MPI_Finalize on every way out of main (mpi_run.hpp; does nothing without mpirun).
struct mpi_session {
  quadmc_cli::mpi::world world;
  ~mpi_session() { quadmc_cli::mpi::finish(); }
};

int quadmc::command_main(int argc, char** argv, const command_options& options) {
  program = options.name;
  quadmc_cli::set_script_folder(options.scripts);
  interruption::install();  // before any thread starts (the signal mask is inherited)
  mpi_session mpi;
  try {
    mpi.world = quadmc_cli::mpi::start(argc, argv);
    interruption::set_quiet(mpi.world.rank != 0);
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: {}\n", program, e.what());
    return exit_failure;
  }

  CLI::App app{program + ": convergence of quadrature rules against Monte Carlo"};
  app.footer(std::string(exit_status_help));
  app.require_subcommand(1);
  // Handled below, not by CLI11, so that its output is checked like every other (standard_output).
  app.set_version_flag("--version", std::string(),
                       "Print the version, git commit, compiler, SIMD levels and plot script");
  bool version = false;

  run_request request;
  unsigned threads = 0;
  auto* run =
      app.add_subcommand("run", "Run a scene and write results/<name>/ (CSV, Markdown, plots)");
  run->add_option("scene", request.scene_file, "Scene file (TOML)")->required();
  run->add_option("--out", request.out_dir, "Output folder (default: results/<scene name>)")
      ->check(quadmc_cli::non_empty_path());
  auto* threads_option =
      run->add_option("--threads", threads,
                      "Threads, 0 = all cores, at most 4096 (default: the scene's `threads`)")
          ->check(CLI::Range(0u, 4096u));
  double timing_min_seconds = 0.0;
  auto* timing_option =
      run->add_option("--timing-min-seconds", timing_min_seconds,
                      "Stable timing: repeat each cell's first estimate until this many seconds "
                      "have passed, 0 to 60; 0 = time it once (default: the scene's "
                      "budget.timing_min_seconds, 0.01)")
          ->check(quadmc_cli::finite_number(0.0, 60.0, "between 0 and 60"));
  run->add_option("--split-cells", request.split_cells,
                  "Under mpirun: which cells all ranks run together, each computing a share of "
                  "its chunks (auto: the costly ones whose method shares chunks; all: every "
                  "cell, those whose method does not share computed whole on every rank; "
                  "none). Results do not depend on it")
      ->check(CLI::IsMember({"auto", "all", "none"}));
  run->add_option("--cells-csv", request.cells_csv,
                  "Write each cell's method's chunk sharing and the rank it ran on (\"split\": "
                  "all ranks) to this CSV file (bench/scaling.py reads it)")
      ->check(quadmc_cli::non_empty_path());

  std::string plan_file;
  auto* plan = app.add_subcommand("plan", "Print the cells a scene would run and what it skips");
  plan->add_option("scene", plan_file, "Scene file (TOML)")->required();

  auto* list = app.add_subcommand("list", "List integrands, methods, point sets and warps");

  std::string folder_a;
  std::string folder_b;
  double tolerance = 0.1;
  auto* compare = app.add_subcommand("compare",
                                     "Compare two results folders; exit 1 when a slope regresses, "
                                     "3 when B lacks what A has (see the footer)");
  compare->add_option("baseline", folder_a, "Results folder A (baseline)")->required();
  compare->add_option("candidate", folder_b, "Results folder B (candidate)")->required();
  compare->add_option("--tolerance", tolerance, "Slope regression tolerance, ≥ 0 (default 0.1)")
      ->check(quadmc_cli::finite_number(0.0, HUGE_VAL, "≥ 0"));

  quadmc_cli::points_request points_request;
  auto* points = quadmc_cli::add_points_subcommand(app, points_request);

  quadmc_cli::gallery_request gallery_request;
  auto* gallery = quadmc_cli::add_gallery_subcommand(app, gallery_request);

  quadmc_cli::render_request render_request;
  auto* render = quadmc_cli::add_render_subcommand(app, render_request);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForVersion&) {
    version = true;
  } catch (const CLI::ParseError& e) {
    // --help is a ParseError with exit code 0: CLI11 prints the help on stdout.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    fmt::print(stderr, "{0}: {1} ({0} --help for usage)\n", program, one_line(e.what()));
    return exit_usage;
  }
  if (threads_option->count() > 0) request.threads = threads;
  if (timing_option->count() > 0) request.timing_min_seconds = timing_min_seconds;

  standard_output out;
  try {
    // A bad QUADMC_SIMD is reported before any work, not from inside the first batch.
    (void)quadmc::active_simd_level();
    if (version) {
      out.print(quadmc_cli::version_text());
      if (out.failed()) throw std::runtime_error(out.message());
      return 0;
    }
    if (*run) return run_command(request, out, mpi.world);
    // Only `run` shares its work between the ranks of mpirun; every other subcommand would run
    // whole on each rank, writing one folder or file from all of them at once (render and
    // gallery did, and the job failed) or printing everything once per rank.
    if (mpi.world.size > 1) {
      const std::string name = app.get_subcommands().empty()
                                   ? std::string("this command")
                                   : app.get_subcommands().front()->get_name();
      throw std::runtime_error(fmt::format(
          "`quadmc {}` runs in one process, not under mpirun ({} ranks): every rank would "
          "write the same output; run it without mpirun (only `quadmc run` is distributed)",
          name, mpi.world.size));
    }
    if (*plan) return plan_command(plan_file, out);
    if (*list) {
      out.print(quadmc_cli::catalogue_listing());
      if (out.failed()) throw std::runtime_error(out.message());
      return 0;
    }
    if (*compare) return compare_command(folder_a, folder_b, tolerance, out);
    if (*points) {
      quadmc_cli::run_points(points_request, [&out](std::string_view text) {
        out.print(text);
        return !out.failed();
      });
      if (out.failed()) throw std::runtime_error(out.message());
      return 0;
    }
    if (*gallery) {
      quadmc_cli::run_gallery(gallery_request, [&out](std::string_view text) { out.print(text); });
      if (out.failed())
        throw std::runtime_error(out.message() + "; the gallery itself was written");
      return 0;
    }
    if (*render) {
      quadmc_cli::run_render(render_request, [&out](std::string_view text) { out.print(text); });
      if (out.failed()) throw std::runtime_error(out.message() + "; the render itself was written");
      return 0;
    }
  } catch (const std::exception& e) {
    // One line: the library's messages are single lines naming file, line, key or parameter.
    // Under mpirun every rank meets the same error; rank 0 says it.
    if (mpi.world.rank == 0) fmt::print(stderr, "{}: {}\n", program, one_line(e.what()));
    // The failure is said: when another rank's exit makes mpirun end this one with SIGTERM while
    // it finalizes MPI, that is no interruption to report (a second line the user did not cause).
    interruption::set_quiet(true);
    return exit_failure;
  }
  return exit_usage;
}
