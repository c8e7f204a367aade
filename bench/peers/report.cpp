// peers.csv and README.md from a study; what they hold: report.hpp.
#include "report.hpp"

#include "targets.hpp"
#include "time_to_accuracy.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gsl/gsl_version.h>
#include <boost/version.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#ifndef QUADMC_PEERS_BUILD
#define QUADMC_PEERS_BUILD "unknown"
#endif
#ifndef QUADMC_PEERS_NOTES
#define QUADMC_PEERS_NOTES ""
#endif

namespace quadmc::peers {
namespace {

// The commands at the top of the README that regenerate results/peers.
constexpr const char* regenerate_command =
    "cmake -S . -B build/peers -G Ninja -DCMAKE_BUILD_TYPE=Release \\\n"
    "  -DCMAKE_CXX_FLAGS_RELEASE='-O2 -DNDEBUG' -DQUADMC_BUILD_TESTS=OFF\n"
    "cmake --build build/peers --target quadmc_peers\n"
    "build/peers/bench/peers/quadmc_peers --out results/peers\n"
    "/usr/bin/python3 bench/peers/plot_peers.py results/peers";

// "Memory constant in N": growth of peak RSS below 4 MiB between the table's two sizes (the
// 512 KiB of chunk slots, the allocator's arenas for a second thread, page-granular noise).
constexpr long memory_bound_kib = 4096;

std::string format_seconds(double t) {
  if (t < 1e-3) return fmt::format("{:.3g} µs", t * 1e6);
  if (t < 1.0) return fmt::format("{:.3g} ms", t * 1e3);
  return fmt::format("{:.3g} s", t);
}

// 10^k written 10ᵏ (for the sizes of the memory table); other numbers as they are.
std::string power_of_ten(std::uint64_t n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  int k = 0;
  std::uint64_t m = n;
  while (m >= 10 && m % 10 == 0) {
    m /= 10;
    ++k;
  }
  if (m != 1 || k == 0) return std::to_string(n);
  return std::string("10") + (k >= 10 ? std::string(digits[k / 10]) : std::string()) +
         digits[k % 10];
}

std::string format_rate(double r) {
  return fmt::format("{:.3g}", r / 1e6);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

struct key {
  std::string method;
  unsigned threads;
  std::string integrand;
  std::size_t s;
  auto operator<=>(const key&) const = default;
};

class report {
 public:
  report(const configuration& c, const study& st) : c_(c), st_(st) {
    for (const row& r : st.rows) {
      if (r.run == "python") continue;  // the Python module's section reads st.python_module
      if (r.run == "uniforms") {        // no integrand: the uniforms section reads them itself
        uniforms_[{r.method, r.n}] = r;
        if (std::find(writers_.begin(), writers_.end(), r.method) == writers_.end()) {
          writers_.push_back(r.method);
        }
        continue;
      }
      if (r.run == "points") {  // no integrand: the QMC section reads them itself
        points_[{r.method, r.s}] = r;
        if (std::find(generators_.begin(), generators_.end(), r.method) == generators_.end()) {
          generators_.push_back(r.method);
        }
        continue;
      }
      if (r.run == "throughput") {
        rate_[{r.method, r.threads, r.integrand, r.s}] = r.rate;
        evaluations_[{r.method, r.threads, r.integrand, r.s}] = r.evaluations;
      }
      if (r.run == "ladder") {
        auto& v = ladder_[{r.method, r.threads, r.integrand, r.s}];
        v.push_back({r.evaluations, r.seconds, r.abs_error});
      }
      if (std::find(integrands_.begin(), integrands_.end(), r.integrand) == integrands_.end()) {
        integrands_.push_back(r.integrand);
      }
      const auto m = std::pair{r.method, r.threads};
      if (r.run == "throughput" &&
          std::find(methods_.begin(), methods_.end(), m) == methods_.end()) {
        methods_.push_back(m);
      }
    }
  }

  std::string markdown() const {
    std::ostringstream o;
    o << "# Peers measured in the same run\n\n";
    o << "quadmc's own methods beside what a user would otherwise pick, on the same integrand "
         "code (quadmc::genz_oscillatory, quadmc::genz_gaussian with "
         "genz_random_parameters(family, "
         "s, 1), and a local sum of coordinates f = Σxⱼ) with the same references "
         "(f.info().exact), measured in one process. Written by `bench/peers/quadmc_peers`; "
         "every number below is in `peers.csv`.\n\n";
    // The answer first, from the tables further down; a quotation, as on the run pages.
    for (const std::string& line : answer_lines()) o << "> - " << line << "\n";
    o << "\n";
    o << "Regenerate (from the repository root; needs libgsl-dev, libcubature-dev, "
         "python3-matplotlib, python3-scipy):\n\n```sh\n"
      << regenerate_command << "\n```\n\n";
    o << fmt::format(
        "Machine: {}, {} hardware threads (shared with other work while measuring); quadmc's "
        "kernels at SIMD level {} (chosen at run time, core/simd_level.hpp). Compiler: "
        "GCC {}; build: {}. GSL {}, Boost {}, cubature (Debian libcubature-dev). Whole run: "
        "{:.0f} s{}; load average (1/5/15 min) {} before, {} after.\n\n",
        cpu_model(), std::thread::hardware_concurrency(),
        quadmc::to_string(quadmc::active_simd_level()), __VERSION__, QUADMC_PEERS_BUILD,
        GSL_VERSION, BOOST_LIB_VERSION, st_.wall_seconds,
        st_.phase_seconds.size() == 3
            ? fmt::format(" (methods and uniforms {:.0f} s, QMC points and the Python module "
                          "{:.0f} s, peak memory {:.0f} s)",
                          st_.phase_seconds[0], st_.phase_seconds[1], st_.phase_seconds[2])
            : std::string(),
        st_.load_before, st_.load_after);
    // The same fields, in the same words, as the header of a `quadmc run` page and meta.csv.
    o << fmt::format(
        "- quadmc: {}, commit {}\n- compiler: {}\n- SIMD levels available: {}\n- rng: {} (the "
        "methods' random streams; docs/theory.md#counter-based-generators)\n\n",
        st_.build.version, st_.build.commit, st_.build.compiler,
        fmt::join(st_.build.simd_levels_available, ", "), st_.build.rng);
    o << "How it is timed: std::chrono::steady_clock around one whole call of each method "
         "(set-up included: point-set construction, GSL state and generator allocation). "
         "**Throughput** rows: N ≥ 2^22 = 4194304 evaluations (2^22 for the Monte Carlo and "
         "Sobol' methods; jittered the smallest k^s ≥ 2^22; tensor rules the smallest "
         "(n+1)^s ≥ 2^22; the lattice (at most 2^20 points) and the digit-scrambled Halton set "
      << fmt::format("(2–5 M points/s) at N = {}", c_.small_throughput_n)
      << "), run in rounds (each round runs every method once, so a burst of load hits all "
         "methods alike) "
      << fmt::format(
             "at least {} times and until {} s of its runs have passed, at most {} times "
             "(a 20 ms run gets {}, runs of ≥ {:.1f} s {}), ",
             c_.min_throughput_runs, c_.min_throughput_seconds, c_.throughput_runs,
             std::min(c_.throughput_runs,
                      static_cast<int>(std::ceil(c_.min_throughput_seconds / 0.02))),
             c_.min_throughput_seconds / c_.min_throughput_runs, c_.min_throughput_runs)
      << "with one seed, the **best** run kept (highest evaluations/s: on a shared machine "
         "noise only slows runs down). **The limit**: `"
      << integrand_only_method
      << "` is the integrand alone — the same object, called as every method calls it "
         "(F::evaluate on a batch of 256 points) — on one batch of independent points "
         "computed before the timing and evaluated again and again, 2^22 evaluations per run: "
         "no point generation, no statistics, no finite check. Every throughput figure is "
         "given as a fraction of its one-thread rate (column `ratio_to_integrand_only` of "
         "peers.csv); its two-thread run (chunks of 48 calls taken from one counter, nothing "
         "else shared) is printed beside the two-thread targets (see \"Targets\"). "
         "**Ladder** rows (work-precision): N = 10², 10^2.5, …, 10⁶ with one thread, for the "
         "peers and quadmc's plain (both generators), jittered, Latin hypercube and tensor "
         "methods (the Sobol', Halton and lattice methods are measured for throughput only; "
         "their work-precision curves are in results/default); random methods with "
      << c_.repetitions
      << " independent seeds, error = RMS over the seeds, time = median over the seeds; each "
         "run repeated at least twice (Boost naive_monte_carlo: once) and until 2 ms have "
         "passed (≤ 100 times), and its fastest repetition kept.\n\n";
    o << fmt::format(
        "quadmc's generators (docs/theory.md#counter-based-generators): every quadmc row draws "
        "its uniforms from Philox4x32-10, the library's default, except `{}`, the same "
        "estimator on the same layout of uniforms drawn from ARS-4x32-7 instead (AES rounds; at "
        "this run's SIMD level its kernel is {}). Both are counter-based, so its estimates are "
        "as reproducible, on 1 or 2 threads, as plain MC's; they differ from them only in the "
        "numbers drawn, not in their distribution. Each generator's own rate, beside the rate at "
        "which this core writes doubles at all, is in \"Uniforms per second\".\n\n",
        plain_mc_ars_method, quadmc::detail::ars_kernel());
    o << "Peers, as called: GSL `gsl_monte_plain/miser/vegas_integrate` with `gsl_rng_mt19937` "
         "(GSL's default), calls = N (VEGAS: N/5 per iteration × its default 5 iterations); "
         "Boost `naive_monte_carlo` with error goal √(V̂/N) (it is goal-driven and polls every "
         "100 ms, so a run lasts ≥ 0.1 s and usually overshoots N; its own `calls()` give the "
         "rate), 1 worker thread and its default (hardware_concurrency); cubature "
         "`hcubature_v`/`pcubature_v` with maxEval = N, tolerances 0 (they get whole batches, "
         "quadmc's layout); Boost `trapezoidal` (max_refinements 20), `gauss_kronrod<double,15>` "
         "(max_depth 15), `tanh_sinh` for s = 1 with tolerances 10⁻² … 10⁻¹²; the scalar "
         "reference loop (xoshiro256+, s uniforms per point, the integrand inlined through a "
         "batch of one, plain sum, `bench/common/scalar_reference_loop.hpp`). Per-point peers call "
         "the suite's integrand through a batch of one (`bench/common/point_adapter.hpp`); "
         "evaluations are counted in every adapter, never assumed.\n\n";
    targets(o);
    throughput(o);
    uniforms(o);
    qmc_points(o);
    python_module(o);
    accuracy(o);
    memory(o);
    determinism(o);
    notes(o);
    o << "## Plots\n\n";
    for (const auto& name : integrands_) {
      o << fmt::format("![work-precision, {0}](work_precision_{0}.svg)\n\n", name);
    }
    if (!st_.skipped.empty()) {
      o << "## Points that could not be run\n\n";
      for (const auto& s : st_.skipped) o << "- " << s << "\n";
      o << "\n";
    }
    return o.str();
  }

 private:
  // The lines at the top of the page, read from its own tables: the targets' tally with the
  // missed ones named, who is fastest to 10⁻³ and to 10⁻⁵ on each integrand and s (quadmc's
  // fastest beside a faster peer), and the most evaluations per second at the largest s.
  std::vector<std::string> answer_lines() const {
    std::vector<std::string> lines;
    const std::vector<target_line> targets =
        evaluate_targets(performance_targets(c_.throughput_n), st_.rows, c_.dimensions);
    const target_tally tally_of = tally(targets);
    // The missed cells grouped by target, in the table's order: how many, and their ratios' range.
    struct missed_target {
      std::string label;
      double goal = 0.0;
      std::size_t cells = 0;
      double low = 0.0, high = 0.0;
    };
    std::vector<missed_target> missed;
    for (const target_line& l : targets) {
      for (const target_cell& c : l.cells) {
        if (c.m != mark::missed || !c.ratio) continue;
        auto it = std::find_if(missed.begin(), missed.end(),
                               [&](const missed_target& m) { return m.label == l.spec.label; });
        if (it == missed.end()) {
          missed.push_back({l.spec.label, l.spec.goal, 0, *c.ratio, *c.ratio});
          it = missed.end() - 1;
        }
        it->cells += 1;
        it->low = std::min(it->low, *c.ratio);
        it->high = std::max(it->high, *c.ratio);
      }
    }
    constexpr std::size_t named = 4;  // the Targets section lists every cell
    std::string line = fmt::format("**Targets:** {} of {} measured ratios met", tally_of.met,
                                   tally_of.met + tally_of.missed);
    if (!missed.empty()) {
      std::vector<std::string> listed;
      for (std::size_t k = 0; k < std::min(named, missed.size()); ++k) {
        const missed_target& m = missed[k];
        listed.push_back(m.cells == 1
                             ? fmt::format("{} ({:.2f}×, goal {}×)", m.label, m.low, m.goal)
                             : fmt::format("{} ({} cells, {:.2f}–{:.2f}×, goal {}×)", m.label,
                                           m.cells, m.low, m.high, m.goal));
      }
      line += fmt::format(
          "; {} missed: {}{}", tally_of.missed, fmt::join(listed, "; "),
          missed.size() > named ? fmt::format("; and {} more targets", missed.size() - named) : "");
    }
    if (tally_of.not_measurable > 0) {
      line += fmt::format("; {} not measurable (⚠)", tally_of.not_measurable);
    }
    lines.push_back(line + " ([Targets](#targets-measured-never-asserted)).");
    for (const double eps : {1e-3, 1e-5}) {
      std::vector<std::string> per_integrand;
      for (const auto& integrand : integrands_) {
        std::vector<std::string> cells;
        for (const std::size_t s : c_.dimensions) {
          struct fastest {
            std::string method;
            time_to_accuracy t;
          };
          std::optional<fastest> all, ours;
          for (const auto& [method, threads] : methods_) {
            const auto it = ladder_.find({method, threads, integrand, s});
            if (it == ladder_.end()) continue;
            const time_to_accuracy t = time_to_reach(it->second, eps);
            if (t.outcome == time_to_accuracy::status::not_reached) continue;
            if (!all || t.seconds < all->t.seconds) all = fastest{method, t};
            if (method.starts_with("quadmc ") && (!ours || t.seconds < ours->t.seconds)) {
              ours = fastest{method, t};
            }
          }
          if (!all) continue;
          const auto timed = [](const fastest& f) {
            return fmt::format("`{}` {}{}", f.method,
                               f.t.outcome == time_to_accuracy::status::at_most ? "≤ " : "",
                               format_seconds(f.t.seconds));
          };
          std::string cell = fmt::format("s = {} {}", s, timed(*all));
          if (ours && ours->method != all->method)
            cell += fmt::format(" (quadmc: {})", timed(*ours));
          if (!ours) cell += " (quadmc: not reached)";
          cells.push_back(cell);
        }
        if (!cells.empty()) {
          per_integrand.push_back(fmt::format("{}: {}", integrand, fmt::join(cells, ", ")));
        }
      }
      lines.push_back(fmt::format(
          "**Fastest to an absolute error of {}** (one thread; \"≤\": below it at the ladder's "
          "first point; quadmc's methods on this ladder are plain (Philox and ARS), jittered, "
          "Latin hypercube and tensor, its Sobol', lattice, Genz–Malik and sparse grids meet the "
          "peers in results/time_to_error): {}.",
          eps == 1e-3 ? "10⁻³" : "10⁻⁵",
          per_integrand.empty() ? std::string("none reached it")
                                : fmt::format("{}", fmt::join(per_integrand, "; "))));
    }
    if (!c_.dimensions.empty()) {
      const std::size_t s = c_.dimensions.back();
      std::vector<std::string> per_integrand;
      for (const auto& integrand : integrands_) {
        const std::optional<double> limit = rate(integrand_only_method, 1, integrand, s);
        std::optional<std::pair<double, std::string>> best;
        for (const auto& [method, threads] : methods_) {
          if (threads != 1 || method == integrand_only_method) continue;
          const std::optional<double> r = rate(method, 1, integrand, s);
          if (r && (!best || *r > best->first)) best = std::pair{*r, method};
        }
        if (!best) continue;
        per_integrand.push_back(fmt::format(
            "{} `{}` {} M/s{}", integrand, best->second, format_rate(best->first),
            limit ? fmt::format(" ({:.2f} of the integrand alone)", best->first / *limit) : ""));
      }
      if (!per_integrand.empty()) {
        lines.push_back(fmt::format("**Most evaluations per second at s = {}** (one thread): {}.",
                                    s, fmt::join(per_integrand, "; ")));
      }
    }
    return lines;
  }

  std::optional<double> rate(const std::string& method, unsigned threads,
                             const std::string& integrand, std::size_t s) const {
    const auto it = rate_.find({method, threads, integrand, s});
    if (it == rate_.end()) return std::nullopt;
    return it->second;
  }

  void targets(std::ostringstream& o) const {
    const std::vector<target_line> lines =
        evaluate_targets(performance_targets(c_.throughput_n), st_.rows, c_.dimensions);
    const target_tally t = tally(lines);
    o << "## Targets (measured, never asserted)\n\n"
         "The goals of docs/design.md#performance-targets, then the first goals that still stand "
         "(plain MC against the scalar loop, GSL and Boost). The current goals replaced the "
         "first ones for jittered points ≥ 0.7× plain MC "
         "(now ≥ 0.85×), tensor Simpson/trapezoid ≥ 2× plain MC (now ≥ 1.5× at s ≥ 2) and "
         "two threads ≥ 1.8× one thread at N ≥ 10⁶ for five methods (now ≥ 1.9× at N ≥ 2^22 "
         "for every method). Ratios of evaluations per second of the throughput rows (one "
         "thread each unless the ratio says otherwise) on the Genz integrands; the Sobol' "
         "point rows compare points per second (section \"Quasi-Monte Carlo points per "
         "second\", s = 2 and 8). ✅ met, ❌ missed, ⚠ not measurable in this run (see below "
         "the table); a ratio with a note in parentheses is shown for information and not "
         "counted: tensor rules at s = 1 (the goal is stated for s ≥ 2: in 1D a grid saves "
         "only the one uniform per point that plain MC draws), plain MC against the integrand "
         "alone at s < 8, with either generator (the goal is stated for s = 8), and the "
         "two-thread ratio of a method whose run is smaller than 2^22 points (the lattice holds "
         "at most 2^20; the Halton set is measured at 2^20 to keep the study short).\n\n"
      << targets_table(lines, c_.dimensions)
      << fmt::format(
             "\n**{} of {} measured ratios met**, {} missed; {} not measurable (⚠). Memory "
             "constant in N: {} — see \"Peak memory\" below. \"cores\": process CPU time / "
             "wall time of the kept run (CLOCK_PROCESS_CPUTIME_ID), i.e. how much of the "
             "machine the run actually got. A ratio is marked ⚠ instead of ✅/❌ when either "
             "of its two runs got less than 0.75 of a core per thread in the best of its "
             "rounds: the machine's other work held a core, so the ratio measures that work, "
             "not the method (scipy runs in a subprocess: its share is not known and never the "
             "reason for ⚠). A vCPU can also be given in full and still run slower, when the "
             "host puts other work on the physical core behind it; \"cores\" cannot see that. "
             "So each two-thread cell also gives \"integrand alone\": the same ratio for the "
             "integrand alone, two threads sharing nothing but a chunk counter, in the same "
             "rounds — what two threads of this machine gave code with nothing to wait for. "
             "It is there to read a cell by, and never changes its mark.\n\n",
             t.met, t.met + t.missed, t.missed, t.not_measurable, memory_summary());
  }

  std::string memory_summary() const {
    int constant = 0;
    for (const auto& r : st_.rss) constant += memory_constant(r, memory_bound_kib) ? 1 : 0;
    return fmt::format("{} of {} methods ✅", constant, st_.rss.size());
  }

  void throughput(std::ostringstream& o) const {
    o << "## Throughput: million evaluations per second\n\n"
         "Per method and thread count; in parentheses the ratio to the scalar reference loop "
         "(same integrand, same s, one thread) and the rate as a percentage of the limit, the "
         "integrand alone on a batch in cache (first row; one thread, so a two-thread method "
         "can pass 100 %). Two threads on a 2-core machine: the ideal is "
         "2× the one-thread figure. † fewer than 10⁵ evaluations: the method stopped early "
         "because it had converged (adaptive 1D rules at their tightest tolerance) or its rule "
         "is exact for the integrand (cubature on the sum of coordinates: error estimate 0 "
         "after one rule application), so the figure is mostly set-up cost, not a rate.\n\n";
    for (const auto& integrand : integrands_) {
      o << "### " << integrand << "\n\n| method | threads |";
      for (std::size_t s : c_.dimensions) o << " s = " << s << " |";
      o << "\n|---|---|";
      for (std::size_t i = 0; i < c_.dimensions.size(); ++i) o << "---|";
      o << "\n";
      for (const auto& [method, threads] : methods_) {
        bool any = false;
        std::string line = fmt::format("| {} | {} |", method, threads);
        for (std::size_t s : c_.dimensions) {
          const auto r = rate(method, threads, integrand, s);
          const auto ref = rate("scalar reference loop", 1, integrand, s);
          if (!r) {
            line += " — |";
            continue;
          }
          any = true;
          const bool short_run = evaluations_.at({method, threads, integrand, s}) < 1e5;
          const auto limit = rate(integrand_only_method, 1, integrand, s);
          line += fmt::format(" {}{} ({:.2f}×, {:.0f} %) |", format_rate(*r), short_run ? " †" : "",
                              ref ? *r / *ref : NAN, limit ? 100.0 * *r / *limit : NAN);
        }
        if (any) o << line << "\n";
      }
      o << "\n";
    }
  }

  // Each generator's uniforms per second beside the rate at which this core stores doubles at
  // all, in cache and in memory: how much of plain MC's cost beyond the integrand is the
  // generator's, and where a generator is held by the memory writes rather than by itself.
  void uniforms(std::ostringstream& o) const {
    if (uniforms_.empty()) return;
    const std::uint64_t small = c_.uniform_cache_doubles;
    const std::uint64_t large = c_.uniform_memory_doubles;
    const std::string ordinary = ordinary_stores_method;
    const std::uint64_t fills = std::max<std::uint64_t>(1, (c_.throughput_n + small - 1) / small);
    o << "## Uniforms per second: Philox and ARS against the memory write rate\n\n"
      << fmt::format(
             "One thread, SIMD level {}; ARS kernel `{}` (`quadmc::detail::ars_kernel()`). "
             "`random_stream::fill_uniform` (core/rng.hpp: the call every random point set "
             "makes) under each generator writes uniforms into a buffer of {} doubles ({} KiB, "
             "which stays in the first-level data cache), filled again and again, each time "
             "with the next uniforms of the stream, {} times per run ({} doubles), and into a "
             "buffer of {} doubles ({} MiB, meant to be larger than the caches, so that the "
             "stores go to memory), filled once per run. Beside them, the write rate itself, "
             "measured the same way: the same buffers written with one value by ordinary "
             "stores, the widest vector stores of the level (bench/peers/memory_write.hpp), and "
             "the large one also by streaming (non-temporal) stores, which write around the "
             "caches without reading each line first. Both buffers are 64-byte aligned and "
             "written once before any timing (no page faults in a timed run). Every writer runs "
             "once per round, {} rounds, std::chrono::steady_clock around the run; its fastest "
             "run is kept. G doubles per second, GB/s = 8 bytes × that, and the rate as a "
             "fraction of the ordinary stores into the same buffer. A measurement, not a "
             "target.\n\n",
             quadmc::to_string(quadmc::active_simd_level()), quadmc::detail::ars_kernel(), small,
             small * sizeof(double) / 1024, fills, fills * small, large,
             large * sizeof(double) >> 20, c_.uniform_rounds);
    o << fmt::format(
        "| writer | kernel | {} KiB buffer: G doubles/s (GB/s) | of the stores | {} MiB buffer: "
        "G doubles/s (GB/s) | of the stores |\n|---|---|---:|---:|---:|---:|\n",
        small * sizeof(double) / 1024, large * sizeof(double) >> 20);
    for (const std::string& w : writers_) {
      std::string kernel;
      std::string cells;
      for (const std::uint64_t n : {small, large}) {
        const auto it = uniforms_.find({w, n});
        const auto store = uniforms_.find({ordinary, n});
        if (it == uniforms_.end()) {
          cells += " — | — |";
          continue;
        }
        const row& r = it->second;
        kernel = r.kernel;
        const double cores = r.cpu_seconds / r.seconds;
        cells += fmt::format(
            " {:.3g} ({:.3g} GB/s){} | {} |", r.rate / 1e9, r.rate * sizeof(double) / 1e9,
            cores < 0.75 ? fmt::format(" ⚠ ({:.2f} cores)", cores) : "",
            store != uniforms_.end() ? fmt::format("{:.2f}", r.rate / store->second.rate)
                                     : std::string("—"));
      }
      o << fmt::format("| {} | {} |{}\n", w, kernel, cells);
    }
    o << "\nA generator whose rate in the large buffer is close to the ordinary stores' is held "
         "there by the memory writes, not by its own arithmetic: a faster generator would not "
         "fill a large array faster. Plain MC never writes its uniforms to memory: it draws "
         "them into a batch of 256 points in cache (core/batching.hpp), so the small buffer's "
         "rate is the one its throughput rows pay. ⚠: the kept run got less than 0.75 of a core "
         "(CPU time / wall time).\n\n";
  }

  // Points per second of the QMC generators, the ratios of quadmc's sets to the peer of the
  // same kind, and whether each peer's points were checked to be of that kind.
  void qmc_points(std::ostringstream& o) const {
    if (generators_.empty() && st_.agreement.empty()) return;
    o << "## Quasi-Monte Carlo points per second\n\n"
      << fmt::format(
             "Million points per second, one thread, N = {} points in each s, best of {} runs "
             "(bench/peers/qmc_point_peers.hpp): every generator writes the same N × s doubles "
             "into an array it allocates inside the timed call, set-up included (scrambles, "
             "GSL's state, scipy's engine). quadmc's sets are generated in batches of 256 "
             "points, as its estimators call them. Boost.Random `sobol_engine<uint32_t, 32>` "
             "(one output per coordinate, × 2^−32), GSL `gsl_qrng_get` (one point per call), "
             "scipy {} `scipy.stats.qmc.Sobol/Halton(d, scramble, seed).random(N)` timed inside "
             "a `/usr/bin/python3` subprocess (interpreter start and import not timed; runs in "
             "one process, not in rounds). No integrand: only point generation.\n\n",
             c_.qmc_points, c_.qmc_point_runs, "1.10 (Debian python3-scipy)");
    if (!generators_.empty()) {
      o << "| generator | family |";
      for (std::size_t s : c_.qmc_dimensions) o << " s = " << s << " |";
      o << "\n|---|---|";
      for (std::size_t i = 0; i < c_.qmc_dimensions.size(); ++i) o << "---:|";
      o << "\n";
      for (const std::string& g : generators_) {
        std::string family;
        std::string line;
        for (std::size_t s : c_.qmc_dimensions) {
          const auto it = points_.find({g, s});
          if (it == points_.end()) {
            line += " — |";
            continue;
          }
          family = it->second.family;
          const double cores = it->second.cpu_seconds / it->second.seconds;
          line += fmt::format(" {}{} |", format_rate(it->second.rate),
                              cores < 0.75 ? fmt::format(" ⚠ ({:.2f} cores)", cores) : "");
        }
        o << fmt::format("| {} | {} |{}\n", g, family, line);
      }
      o << "\n⚠: the kept run got less than 0.75 of a core (CPU time / wall time), so it "
           "measured the machine's other work too.\n\n";
      // quadmc's set of the same kind as each peer (what check_point_agreement compares).
      const std::vector<std::pair<std::string, std::string>> pairs{
          {"quadmc sobol none", "Boost.Random sobol_engine"},
          {"quadmc sobol none", "GSL sobol"},
          {"quadmc sobol none", "GSL niederreiter_2"},
          {"quadmc sobol none", "scipy Sobol"},
          {"quadmc sobol lms_shift", "scipy Sobol scrambled"},
          {"quadmc halton none", "GSL halton"},
          {"quadmc halton none", "scipy Halton"},
          {"quadmc halton permutation", "GSL reversehalton"},
          {"quadmc halton permutation", "scipy Halton scrambled"}};
      o << "quadmc / peer, points per second (> 1: quadmc is faster):\n\n| quadmc | peer |";
      for (std::size_t s : c_.qmc_dimensions) o << " s = " << s << " |";
      o << "\n|---|---|";
      for (std::size_t i = 0; i < c_.qmc_dimensions.size(); ++i) o << "---:|";
      o << "\n";
      for (const auto& [ours, peer] : pairs) {
        o << fmt::format("| {} | {} |", ours, peer);
        for (std::size_t s : c_.qmc_dimensions) {
          const auto a = points_.find({ours, s});
          const auto b = points_.find({peer, s});
          if (a == points_.end() || b == points_.end()) {
            o << " — |";
          } else {
            o << fmt::format(" {:.2f}× |", a->second.rate / b->second.rate);
          }
        }
        o << "\n";
      }
      o << "\n";
    }
    if (!st_.agreement.empty()) {
      o << "Same kind of points (checked in this run on the generators' own output, and by "
           "tests/peers/qmc_point_peers_test.cpp):\n\n";
      for (const point_agreement& a : st_.agreement) {
        o << fmt::format("- {} **{}**: {} ({})\n", a.holds ? "✅" : "❌", a.peer, a.claim, a.detail);
      }
      o << "\n";
    }
  }

  // The Python module against scipy and its own C++ (python_module_speed.hpp): two tables of
  // medians with their range, and the ratios with what explains them.
  void python_module(std::ostringstream& o) const {
    const python_module_study& p = st_.python_module;
    o << "## The Python module: quadmc.points against scipy, a numpy integrand against C++\n\n";
    if (p.timings.empty()) {
      o << "Not measured in this run: " << p.skipped << ".\n\n";
      return;
    }
    const python_timing* any = &p.timings.front();
    o << fmt::format(
        "`import quadmc` (bench/python/, built with this run's flags) timed by "
        "`bench/peers/python_module_speed.py` in one `/usr/bin/python3` process (numpy, scipy: "
        "{}), every contender of a table once per round, in {} alternating rounds after one to "
        "warm up, with time.perf_counter around the call alone; each cell is the **median** of "
        "the rounds in ms, with the fastest and slowest round in parentheses. One thread "
        "throughout (quadmc.points runs on one; quadmc.integrate is given threads=1 for the "
        "catalogue integrand, and runs a Python callable on one). \"cores\": process CPU time / "
        "wall time over the rounds, as in the tables above. s = {}, N = 2^{} = {}.\n\n",
        p.versions, any->rounds, any->s, std::bit_width(any->n) - 1, any->n);
    auto ms = [](const python_timing* t) {
      if (t == nullptr) return std::string("—");
      return fmt::format("{:.2f} ({:.2f}–{:.2f}), {:.2f} cores", 1e3 * t->median, 1e3 * t->min,
                         1e3 * t->max, t->cores);
    };
    auto median = [&](const std::string& group, const std::string& key) {
      const python_timing* t = p.find(group, key);
      return t != nullptr ? t->median : NAN;
    };
    const std::vector<std::pair<std::string, std::string>> points{
        {"quadmc_points", "`quadmc.points('sobol', N, 8, seed, randomization='lms_shift')`"},
        {"scipy_points", "`scipy.stats.qmc.Sobol(8, scramble=True, seed).random(N)`"},
        {"numpy_ones", "`numpy.ones((N, 8))`: a fresh 64 MiB array, written once"}};
    o << "| points, s = 8, N = 2^20 (64 MiB) | fresh memory (as a user gets it) | reused memory "
         "(no first touch) |\n|---|---|---|\n";
    for (const auto& [key, label] : points) {
      o << fmt::format("| {} | {} | {} |\n", label, ms(p.find("points", key)),
                       ms(p.find("points_reused", key)));
    }
    const double quadmc = median("points", "quadmc_points");
    const double scipy = median("points", "scipy_points");
    const double ones = median("points", "numpy_ones");
    const double quadmc_reused = median("points_reused", "quadmc_points");
    const double scipy_reused = median("points_reused", "scipy_points");
    const double ones_reused = median("points_reused", "numpy_ones");
    const double ratio = scipy / quadmc;
    const python_timing* quadmc_best = p.find("points", "quadmc_points");
    const python_timing* scipy_best = p.find("points", "scipy_points");
    const double best_ratio =
        quadmc_best != nullptr && scipy_best != nullptr ? scipy_best->min / quadmc_best->min : NAN;
    // Differences of medians are taken within one contender (fresh − reused) or within one
    // memory setting (quadmc − numpy.ones, both reused), never across both: under load two
    // medians of different calls in different memory can even come out in the wrong order.
    o << fmt::format(
        "\n**scipy / quadmc.points = {:.2f}×** (medians, fresh memory, both calls as written "
        "above, set-up included; {:.2f}× between their fastest rounds); the goal of ≥ 5× is "
        "**{}**. In reused memory (glibc's malloc told to keep what is freed, so every round "
        "writes into pages an earlier one touched): {:.2f}×. Where the time goes: a fresh "
        "64 MiB result pays its first touch (Linux maps and zeroes each page the first time it "
        "is written): `numpy.ones` takes {:.2f} ms fresh and {:.2f} ms reused, so the first "
        "touch alone costs about {:.1f} ms, while quadmc.points' own work beyond writing the "
        "array (its reused time minus `numpy.ones`' reused time: the Sobol' points, their LMS "
        "scramble and shift) is {:.1f} ms; fresh minus reused is {:.1f} ms for quadmc.points "
        "and {:.1f} ms for scipy. A quadmc.points that cost no more than a fresh `numpy.ones` "
        "would be {:.2f}× faster than scipy here{}. ",
        ratio, best_ratio, ratio >= 5.0 ? "met ✅" : "missed ❌", scipy_reused / quadmc_reused,
        1e3 * ones, 1e3 * ones_reused, 1e3 * (ones - ones_reused),
        1e3 * (quadmc_reused - ones_reused), 1e3 * (quadmc - quadmc_reused),
        1e3 * (scipy - scipy_reused), scipy / ones,
        scipy / ones < 5.0
            ? ": on one thread, with a fresh result, 5× is out of reach on this machine, however "
              "fast the points"
            : "");
    const auto cxx = points_.find({"quadmc sobol lms_shift", any->s});
    o << fmt::format(
        "quadmc.points writes the points through a 256-point buffer in cache into the numpy "
        "array (points_over, estimators/point_set_catalogue.cpp), the bits `quadmc points` "
        "writes: {:.0f} M points/s in reused memory, against {} for the C++ row `quadmc sobol "
        "lms_shift` at s = {} in the table above (N = {}, generated straight into its "
        "array).\n\n",
        static_cast<double>(any->n) / quadmc_reused / 1e6,
        cxx != points_.end() ? fmt::format("{:.0f} M points/s", cxx->second.rate / 1e6)
                             : std::string("— (not measured)"),
        any->s, c_.qmc_points);

    const std::vector<std::pair<std::string, std::string>> integrand{
        {"integrate_catalogue",
         "`quadmc.integrate(quadmc.integrand('genz_gaussian', 8, a, u), 'plain_mc', N, "
         "threads=1)`: C++"},
        {"integrate_numpy",
         "`quadmc.integrate(f, 'plain_mc', N, s=8)`, f the same integrand in numpy "
         "(`exp(-((x - u)**2) @ a**2)`), called on blocks of 12288 points"},
        {"integrate_ones",
         "`quadmc.integrate(g, 'plain_mc', N, s=8)`, g returning `numpy.ones(m)`"},
        {"numpy_all", "f on the N points in one call (no quadmc.integrate)"},
        {"numpy_batches", "f on the same points in the same 86 blocks"},
        {"catalogue_batches", "the catalogue integrand on the same 86 blocks (C++)"}};
    o << "| genz_gaussian, s = 8, N = 2^20, one thread | median (range) ms |\n|---|---|\n";
    for (const auto& [key, label] : integrand) {
      o << fmt::format("| {} | {} |\n", label, ms(p.find("integrand", key)));
    }
    const double c = median("integrand", "integrate_catalogue");
    const double numpy = median("integrand", "integrate_numpy");
    const double calls_alone = median("integrand", "integrate_ones");
    const double numpy_batches = median("integrand", "numpy_batches");
    const double catalogue_batches = median("integrand", "catalogue_batches");
    // quadmc.integrate calls a callable once per block of at most 2^14 points within a Monte
    // Carlo chunk of 12288 (bench/python/integrate.cpp): 2^20 points are 86 calls.
    // integrate_ones = point generation and sums + the calls; integrate_catalogue −
    // catalogue_batches = point generation and sums without the C++ evaluation: the difference is
    // the calls (the crossing, the copy of the block into a new array, numpy.ones).
    constexpr double calls = 86.0;
    const double kernel = c - catalogue_batches;
    const double per_call = (calls_alone - kernel) / calls;
    const double share = calls * per_call / numpy;
    // What the numpy run spends beyond the kernel's own work and numpy's arithmetic on the same
    // blocks: the calls, measured as a difference of medians rather than derived from g.
    const double beyond = numpy - kernel - numpy_batches;
    o << fmt::format(
        "\n**A numpy integrand through quadmc.integrate takes {:.2f}× the time of the same "
        "integrand in C++** (medians: {:.1f} ms against {:.1f} ms), an overhead of {:.0f} %. "
        "Nearly all of it is numpy's own arithmetic: {:.2f}× the C++ batch evaluate on the same "
        "blocks ({:.1f} ms against {:.1f} ms, no quadmc.integrate around either), which no "
        "batching removes. What the calls cost this numpy integrand, measured directly: the "
        "numpy run minus the kernel's own work ({:.1f} ms: the C++ run minus its evaluation) "
        "minus numpy on the same blocks leaves {:.1f} ms, {:.1f} % of the run (goal: a call "
        "overhead below 10 % on large blocks, **{}**; a difference of medians, so within their "
        "spread). For a callable that does not read its points (g), the calls cost {:.1f} µs "
        "each (g's run minus the kernel's work, over 86 calls), {:.1f} % of the numpy run: "
        "mostly the copy of each block into the fresh array f is given (64 MiB in all), which a "
        "numpy f then reads from cache rather than from memory, so the two figures differ.\n\n",
        numpy / c, 1e3 * numpy, 1e3 * c, 100.0 * (numpy / c - 1.0),
        numpy_batches / catalogue_batches, 1e3 * numpy_batches, 1e3 * catalogue_batches,
        1e3 * kernel, 1e3 * beyond, 100.0 * beyond / numpy,
        beyond / numpy < 0.1 ? "met ✅" : "missed ❌", 1e6 * per_call, 100.0 * share);
  }

  void accuracy(std::ostringstream& o) const {
    o << "## Time to reach an absolute error of 10⁻³ and 10⁻⁵\n\n"
         "Interpolated on the work-precision ladder (one thread; log time against log error "
         "between the last point above ε and the first of the tail that stays below); "
         "\"≤ t\": already below ε at the smallest ladder point; \"not reached\": not within "
         "the ladder (N ≤ 10⁶, or the peer's own limit). Random methods: RMS error over the "
         "seeds, so one lucky seed does not count.\n\n";
    for (const auto& integrand : integrands_) {
      o << "### " << integrand << "\n\n| method |";
      for (std::size_t s : c_.dimensions) o << " s = " << s << ": 10⁻³ | 10⁻⁵ |";
      o << "\n|---|";
      for (std::size_t i = 0; i < c_.dimensions.size(); ++i) o << "---|---|";
      o << "\n";
      for (const auto& [method, threads] : methods_) {
        bool any = false;
        std::string line = "| " + method + " |";
        for (std::size_t s : c_.dimensions) {
          const auto it = ladder_.find({method, threads, integrand, s});
          if (it == ladder_.end()) {
            line += " — | — |";
            continue;
          }
          any = true;
          for (double eps : {1e-3, 1e-5}) {
            const time_to_accuracy t = time_to_reach(it->second, eps);
            switch (t.outcome) {
              case time_to_accuracy::status::reached:
                // fmt rather than " " + string: GCC 12 at -O3 warns a false -Wrestrict there.
                line += fmt::format(" {} |", format_seconds(t.seconds));
                break;
              case time_to_accuracy::status::at_most:
                line += fmt::format(" ≤ {} |", format_seconds(t.seconds));
                break;
              case time_to_accuracy::status::not_reached:
                line += " not reached |";
                break;
            }
          }
        }
        if (any) o << line << "\n";
      }
      o << "\n";
    }
  }

  void memory(std::ostringstream& o) const {
    o << "## Peak memory of quadmc's methods\n\n"
         "Peak RSS (VmHWM of /proc/self/status, read by the child at its end) of a fresh child "
         "process — this program re-executed as `quadmc_peers --one METHOD genz_gaussian 2 N 2` "
         "— that integrates Genz Gaussian, s = 2, with 2 threads. Not getrusage's ru_maxrss: "
         "Linux carries it over fork and exec, so a child would report the parent's peak "
         "(bench/common/peak_rss.hpp). Jittered and tensor sizes are the nearest valid ones "
         "(k² and (n+1)²); the lattice holds at most 2^20 points, so it is run at 2^19 and "
         "2^20, and the Halton set (2–5 M points/s) at most at 10⁷ to keep the study short "
         "(their N in parentheses). Baseline: the same child doing no integration "
         "(libraries, one integrand). What grows with N is bounded: parallel_reduce folds at "
         "most 4096 chunk results at a time (core/parallel_reduce.hpp), so the slots stop "
         "growing at 4096 chunks — 4096 × 128-byte sample_statistics = 512 KiB for Monte Carlo "
         "(reached at 5·10⁷ points), 4096 × 16-byte Neumaier sums for tensor rules — whatever "
         "N; nothing is stored per point. "
      << fmt::format(
             "**Constant in N** (✅): growth below {} MiB between the two sizes — the bounded "
             "slots plus page-granular noise; storing one byte per point would add {:.0f} MiB "
             "between {} and {} points.\n\n",
             memory_bound_kib / 1024,
             static_cast<double>(c_.rss_sizes.back() - c_.rss_sizes.front()) / (1 << 20),
             power_of_ten(c_.rss_sizes.front()), power_of_ten(c_.rss_sizes.back()))
      << "| method |";
    for (std::uint64_t n : c_.rss_sizes) o << " N = " << power_of_ten(n) << " |";
    o << " growth | constant in N |\n|---|";
    for (std::size_t i = 0; i <= c_.rss_sizes.size() + 1; ++i) o << "---|";
    o << "\n";
    o << fmt::format("| baseline (no integration) | {} KiB |", st_.rss_baseline_kib);
    for (std::size_t i = 1; i < c_.rss_sizes.size(); ++i) o << " |";
    o << " | |\n";
    for (const auto& r : st_.rss) {
      o << "| " << r.method << " |";
      for (std::size_t i = 0; i < r.kib.size(); ++i) {
        o << " " << r.kib[i] << " KiB";
        if (i < r.n.size() && i < c_.rss_sizes.size() && r.n[i] != c_.rss_sizes[i]) {
          o << " (N = " << r.n[i] << ")";
        }
        o << " |";
      }
      o << fmt::format(" {:+} KiB | {} |\n", r.kib.back() - r.kib.front(),
                       memory_constant(r, memory_bound_kib) ? "✅" : "❌");
    }
    o << "\n";
  }

  void determinism(std::ostringstream& o) const {
    if (!st_.repro) return;
    const auto& r = *st_.repro;
    o << "## Same seed, same answer?\n\n";
    o << fmt::format(
        "{}, s = {}, N = {}: quadmc plain MC with 1 thread gives {:.17g}, with 2 threads {:.17g} "
        "({}). Boost naive_monte_carlo (default threads) run {} times with the same seed and "
        "error goal:",
        r.integrand, r.s, c_.throughput_n, r.quadmc_one_thread, r.quadmc_two_threads,
        std::bit_cast<std::uint64_t>(r.quadmc_one_thread) ==
                std::bit_cast<std::uint64_t>(r.quadmc_two_threads)
            ? "bitwise identical"
            : "**different bits**",
        r.boost_values.size());
    for (double v : r.boost_values) o << fmt::format(" {:.17g}", v);
    bool same = true;
    for (double v : r.boost_values) same &= v == r.boost_values.front();
    o << (same ? " (identical this time).\n\n"
               : " — it changes from run to run: its threads race to the goal and the master "
                 "stops them at a time-dependent point.\n\n");
  }

  void notes(std::ostringstream& o) const {
    std::ifstream in(QUADMC_PEERS_NOTES);
    // Read into a string first: streaming an empty rdbuf() would set failbit on `o`.
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!text.empty()) o << text << "\n";
  }

  const configuration& c_;
  const study& st_;
  std::map<key, double> rate_;
  std::map<key, double> evaluations_;  // evaluations of the kept throughput run
  std::map<key, std::vector<ladder_point>> ladder_;
  std::vector<std::string> integrands_;
  std::vector<std::pair<std::string, unsigned>> methods_;
  std::map<std::pair<std::string, std::size_t>, row> points_;      // QMC rows by (generator, s)
  std::map<std::pair<std::string, std::uint64_t>, row> uniforms_;  // by (writer, buffer doubles)
  std::vector<std::string> writers_;     // of the uniforms rows, in order of first appearance
  std::vector<std::string> generators_;  // in order of first appearance
};

}  // namespace

void write_csv(const std::filesystem::path& path, const std::vector<row>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "method,integrand,s,threads,N,evaluations,seconds,evals_per_second,abs_error,"
         "ratio_to_scalar_loop,run,family,control,repetitions,cpu_seconds,"
         "ratio_to_integrand_only,seconds_min,seconds_max,kernel\n";
  for (const row& r : rows) {
    out << fmt::format(
        "{},{},{},{},{},{:.0f},{:.6g},{:.6g},{},{},{},{},{},{},{},{},{},{},{}\n", r.method,
        r.integrand, r.s, r.threads, r.n, r.evaluations, r.seconds, r.rate,
        std::isnan(r.abs_error) ? std::string() : fmt::format("{:.6g}", r.abs_error),
        r.ratio_to_scalar_loop ? fmt::format("{:.4f}", *r.ratio_to_scalar_loop) : std::string(),
        r.run, r.family, r.control, r.repetitions,
        (r.run == "throughput" || r.run == "points" || r.run == "uniforms") &&
                !std::isnan(r.cpu_seconds)
            ? fmt::format("{:.6g}", r.cpu_seconds)
            : std::string(),
        r.ratio_to_integrand_only ? fmt::format("{:.4f}", *r.ratio_to_integrand_only)
                                  : std::string(),
        std::isnan(r.seconds_min) ? std::string() : fmt::format("{:.6g}", r.seconds_min),
        std::isnan(r.seconds_max) ? std::string() : fmt::format("{:.6g}", r.seconds_max), r.kernel);
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string() + " completely");
}

void write_meta_csv(const std::filesystem::path& path, const study& st) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << quadmc::meta_csv_text(st.build);
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string() + " completely");
}

void write_markdown_report(const std::filesystem::path& path, const configuration& c,
                           const study& st) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << report(c, st).markdown();
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string() + " completely");
}

}  // namespace quadmc::peers
