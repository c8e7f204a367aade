// quadmc_peers: quadmc's plain Monte Carlo (on Philox's uniforms and on ARS's), jittered and Latin
// hypercube points, scrambled Sobol', Halton and lattice points and tensor Simpson/trapezoid, each
// beside the integrand alone on a batch in cache (the limit of its rate), and the performance
// targets marked met or missed (targets.hpp), measured in one run beside what a user would
// otherwise pick — a hand-written xoshiro256+ loop, GSL plain/MISER/VEGAS, Boost.Math
// naive_monte_carlo and its 1D rules, cubature's hcubature/pcubature — on the same integrands (Genz
// oscillatory and Gaussian, the sum of coordinates) with the same references, for s ∈ {1, 2, 4, 8}:
// evaluations per second, time to 10⁻³ and 10⁻⁵, peak memory, and whether a fixed seed fixes the
// answer; and quasi-Monte Carlo point generation (quadmc's Sobol', Halton and lattice sets beside
// Boost.Random, GSL and scipy.stats.qmc: qmc_point_peers.hpp) in points per second; and the Python
// module `quadmc` against scipy.stats.qmc and against its own C++ (python_module_speed.hpp); and
// the two generators' uniforms per second beside the rate at which the core writes doubles at all.
//
//   quadmc_peers [--out DIR] [--quick]        writes DIR/peers.csv, DIR/meta.csv, DIR/README.md
//   quadmc_peers --one METHOD INTEGRAND S N THREADS
//                                             one method once; prints its peak RSS in KiB
//   /usr/bin/python3 bench/peers/plot_peers.py DIR   then draws DIR/work_precision_*.svg
//
// This file is the command line and the order of the steps; the steps live in
// measurement.hpp (ladder, throughput, uniforms per second), peak_memory.hpp (`--one` and the
// memory table) and report.hpp (CSV and Markdown). Not a test and not part of CI: the full run
// takes about three minutes on 2 cores, and nothing in it is asserted (targets are reported, met or
// not). Exit status: 0 done, 1 a failed run (one line on stderr), 2 a command-line error.
#include "build_provenance.hpp"
#include "measurement.hpp"
#include "peak_memory.hpp"
#include "report.hpp"
#include "study.hpp"

#include "quadmc/core/rng.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <charconv>
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace quadmc::peers {
namespace {

// A decimal integer ≥ minimum, the whole text and nothing else ("-5", "2x", "" are rejected).
std::optional<std::uint64_t> parse_count(const std::string& text, std::uint64_t minimum) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || value < minimum) return std::nullopt;
  return value;
}

std::string names(std::span<const std::string_view> list) {
  std::string out;
  for (std::string_view n : list) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// `--one METHOD INTEGRAND S N THREADS`, checked: one line naming the argument on a bad value.
int one_command(const std::vector<std::string>& a) {
  const auto s = parse_count(a[2], 1);
  const auto n = parse_count(a[3], 1);
  const auto threads = parse_count(a[4], 0);
  auto bad = [](std::string_view what, const std::string& value, std::string_view expected) {
    std::cerr << fmt::format("quadmc_peers: --one {}: expected {}, got '{}'\n", what, expected,
                             value);
    return 2;
  };
  if (!s) return bad("S", a[2], "an integer ≥ 1 (the dimension)");
  if (!n) return bad("N", a[3], "an integer ≥ 1 (the number of points)");
  if (!threads || *threads > 4096) return bad("THREADS", a[4], "an integer 0…4096 (0 = all cores)");
  return run_one(a[0], a[1], *s, *n, static_cast<unsigned>(*threads));
}

int study_command(const std::filesystem::path& out, bool quick) {
  const auto start = std::chrono::steady_clock::now();
  const configuration c = quick ? quick_configuration() : configuration{};
  study st;
  st.build = quadmc::bench::build_provenance();
  // Both generators run here: "quadmc plain MC" and the point sets on Philox, the library's
  // default, "quadmc plain MC (ARS)" and a row of the uniforms table on ARS.
  st.build.rng =
      fmt::format("{} {}", to_string(rng_kind::philox4x32_10), to_string(rng_kind::ars4x32_7));
  st.load_before = load_average();
  auto since_start = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  measure_methods(c, st);
  measure_uniforms(c, st);
  st.phase_seconds.push_back(since_start());
  measure_qmc_points(c, st);
  measure_python_module(c, st);
  st.phase_seconds.push_back(since_start() - st.phase_seconds[0]);
  measure_peak_memory(c, st);
  st.load_after = load_average();
  st.wall_seconds = since_start();
  st.phase_seconds.push_back(st.wall_seconds - st.phase_seconds[0] - st.phase_seconds[1]);

  std::filesystem::create_directories(out);
  write_csv(out / "peers.csv", st.rows);
  write_meta_csv(out / quadmc::meta_csv_file, st);
  write_markdown_report(out / "README.md", c, st);
  std::cerr << fmt::format(
      "wrote {}/peers.csv, meta.csv and README.md in {:.0f} s (methods and uniforms {:.0f} s, QMC "
      "points and the Python module {:.0f} s, peak memory {:.0f} s)\n",
      out.string(), st.wall_seconds, st.phase_seconds[0], st.phase_seconds[1], st.phase_seconds[2]);
  return 0;
}

int run(int argc, char** argv) {
  CLI::App app{
      "quadmc_peers: quadmc's methods beside GSL, Boost.Math, cubature and a hand-written loop, "
      "on the same integrands; writes DIR/peers.csv and DIR/README.md"};
  std::string out = "results/peers";
  bool quick = false;
  std::vector<std::string> one;
  auto* out_option =
      app.add_option("--out", out, "Output folder (default: results/peers)")->type_name("DIR");
  auto* quick_flag =
      app.add_flag("--quick", quick, "A smoke run (small N, seconds): numbers not for the record");
  app.add_option("--one", one,
                 fmt::format("Run one method once and print its peak RSS in KiB (the peak-memory "
                             "children; a profiler's target). METHOD: {}; INTEGRAND: {}; S ≥ 1, "
                             "N ≥ 1, THREADS 0…4096 (0 = all cores)",
                             names(one_run_methods()), names(one_run_integrands())))
      ->expected(5)
      ->type_name("METHOD INTEGRAND S N THREADS")
      ->excludes(out_option)
      ->excludes(quick_flag);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "quadmc_peers: " << e.what() << " (run with --help)\n";
    return 2;
  }
  if (!one.empty()) return one_command(one);
  return study_command(out, quick);
}

}  // namespace
}  // namespace quadmc::peers

int main(int argc, char** argv) {
  try {
    return quadmc::peers::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "quadmc_peers: " << e.what() << "\n";
    return 1;
  }
}
