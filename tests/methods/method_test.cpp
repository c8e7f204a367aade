// Tests of method.hpp's shares_chunks: for every registered method, under every control it
// supports and every option value that changes its kernel (the rules' accumulators, the sparse
// grids' rules, the quasi-Monte Carlo randomizations, importance's warps and point sets; the
// external methods and the external point set on files written here), one cell
// is run by two "processes" (threads of this test, each with its own exchange of an in-process
// group) and once alone. Both processes must return the lone run's bits, and the flag must say
// what happened: a method that shares chunks had every reduction exchanged (none ran whole) and
// its processes evaluated the integrand between them exactly as often as the lone run, each
// less; one that does not had nothing exchanged and each process evaluated as often as the lone
// run. So the MPI planner (bench/quadmc/mpi_run.hpp), which splits only cells whose method
// shares, can trust the flag.
#include "quadmc/methods/method.hpp"

#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "support/in_process_group.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace quadmc {
namespace {

using test_support::in_process_group;

// Integrand evaluations made on the calling thread (the runs below use one thread per process,
// so every chunk runs on its process's own thread).
thread_local std::uint64_t evaluations_here = 0;

struct counting_integrand {
  any_integrand f;
  std::size_t dimension() const noexcept { return f.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    evaluations_here += y.size();
    f.evaluate(x, y);
  }
  integrand_info info() const { return f.info(); }
};

struct candidate {
  const char* family;
  std::size_t s;
};

// The first integrand a method takes: a Genz family in 2D, eˣ for 1D methods, the irradiance
// integrand for the rendering estimators.
constexpr candidate candidates[] = {{"genz_gaussian", 2}, {"exp", 1}, {"irradiance_area", 2}};

// The path template of the files the external methods read for the cells below (N = 2^16 points
// of the first candidate, s = 2, repetition 0): a 2D grid of cell centres, weights 1/N for the
// rule. Written once per test program into a folder removed when it ends.
std::filesystem::path external_files(bool weighted) {
  static const test_support::temporary_directory dir(
      "method_test_external", test_support::temporary_directory::start::empty);
  const std::filesystem::path file = dir.path / (weighted ? "rule_65536_0.csv" : "65536_0.csv");
  if (!std::filesystem::exists(file)) {
    std::string text;
    for (std::uint64_t i = 0; i < 65536; ++i) {
      text += fmt::format("{},{}{}\n", (static_cast<double>(i % 256) + 0.5) / 256,
                          (static_cast<double>(i / 256) + 0.5) / 256,
                          weighted ? fmt::format(",{}", 1.0 / 65536) : std::string());
    }
    std::ofstream(file, std::ios::binary) << text;
  }
  return dir.path / (weighted ? "rule_{N}_{r}.csv" : "{N}_{r}.csv");
}

// The same for importance's 1D uniforms (point_set = "external_points"): N = 2^16 midpoints.
std::filesystem::path uniform_files_1d() {
  static const test_support::temporary_directory dir(
      "method_test_uniforms", test_support::temporary_directory::start::empty);
  const std::filesystem::path file = dir.path / "65536_0.csv";
  if (!std::filesystem::exists(file)) {
    std::string text;
    for (std::uint64_t i = 0; i < 65536; ++i) {
      text += fmt::format("{}\n", (static_cast<double>(i) + 0.5) / 65536);
    }
    std::ofstream(file, std::ios::binary) << text;
  }
  return dir.path / "{N}_{r}.csv";
}

// Every option value that selects another kernel path, per method; {} is the defaults.
std::vector<option_table> configurations(std::string_view name) {
  const std::string n(name);
  if (n.find("rectangle") != std::string::npos || n == "midpoint" || n == "trapezoid" ||
      n == "simpson" || n == "gauss_legendre") {
    std::vector<option_table> out{{}};
    for (const char* a : {"pairwise", "neumaier", "naive", "long_double"}) {
      out.push_back({{"accumulator", a}});
    }
    return out;
  }
  if (n == "smolyak") {
    return {{}, {{"rule", "gauss_patterson"}}, {{"rule", "trapezoid"}}};
  }
  if (n == "adaptive_sparse_grid") return {{}, {{"rule", "gauss_patterson"}}};
  // A quasi-Monte Carlo method takes its set's own keys: every other choice of each.
  if (const point_set_entry* set = find_point_set(n); set != nullptr && !set->options.empty()) {
    std::vector<option_table> out{{}};
    for (const point_set_option& o : set->options) {
      for (std::size_t i = 1; i < o.choices.size(); ++i) {
        // An integer choice is a number in a table (interlacing = 2), a string choice a string.
        const option_value value = o.integer ? option_value(std::stod(std::string(o.choices[i])))
                                             : option_value(std::string(o.choices[i]));
        out.push_back({{std::string(o.key), value}});
      }
    }
    return out;
  }
  if (n == "importance") {
    return {{{"warp", "exponential"}},
            {{"warp", "power"}},
            {{"warp", "exponential"}, {"point_set", "jittered"}},
            {{"warp", "exponential"}, {"point_set", "sobol"}},
            {{"warp", "power"},
             {"point_set", "external_points"},
             {"path", uniform_files_1d().string()}}};
  }
  if (n.rfind("irradiance_", 0) == 0) {
    return {{},
            {{"point_set", "sobol"}},
            {{"point_set", "external_points"}, {"path", external_files(false).string()}}};
  }
  if (n == "external_points" || n == "external_rule") {
    return {{{"path", external_files(n == "external_rule").string()}}};
  }
  return {{}};
}

struct process_outcome {
  repetition_result result;
  std::uint64_t evaluations = 0;
  std::uint64_t windows_shared = 0;
  std::uint64_t chunks_whole = 0;
  std::string error;
};

bool same_bits(const repetition_result& a, const repetition_result& b) {
  return std::bit_cast<std::uint64_t>(a.value) == std::bit_cast<std::uint64_t>(b.value) &&
         std::bit_cast<std::uint64_t>(a.std_error) == std::bit_cast<std::uint64_t>(b.std_error) &&
         std::bit_cast<std::uint64_t>(a.error_estimate) ==
             std::bit_cast<std::uint64_t>(b.error_estimate) &&
         a.evaluations == b.evaluations;
}

// N = 2^16: at least 4 chunks of every kernel (2^14 points for rules, 12288 samples for Monte
// Carlo), so that a shared cell leaves each of two processes less than the whole.
constexpr std::uint64_t N = std::uint64_t{1} << 16;

TEST(MethodSharesChunks, SaysWhatTheKernelsDoUnderAChunkExchange) {
  std::set<std::string> covered;
  for (const method_descriptor* d : method_registry()) {
    for (const option_table& options : configurations(d->name)) {
      const std::unique_ptr<const method> m = make_method(d->name, options);
      const candidate* chosen = nullptr;
      for (const candidate& c : candidates) {
        const catalogue_entry& entry = find_catalogue_entry(c.family);
        if (!m->incompatibility({entry.name, c.s, entry.rendering}) && m->size_for(N, c.s).size) {
          chosen = &c;
          break;
        }
      }
      ASSERT_NE(chosen, nullptr) << d->name << " takes none of the test's integrands";
      integrand_params params;
      params.dimension = chosen->s;
      params.seed = 3;
      if (find_catalogue_entry(chosen->family).rendering) params.scalars["occluder"] = 1.0;
      const any_integrand f(counting_integrand{make_integrand(chosen->family, params)});
      const cell_size size = *m->size_for(N, chosen->s).size;
      for (const cell_control control : d->controls) {
        // A control the configuration leaves no rule for is refused when the scene is read.
        if (m->refuses(control)) continue;
        std::string where = std::string(d->name) + std::string(m->label_suffix()) + " (" +
                            std::string(to_string(control)) + ") on " + chosen->family;
        const double tolerance =
            control == cell_control::tolerance ? 1e-7 : std::numeric_limits<double>::quiet_NaN();
        const method_cell cell{f, params, size, control, tolerance, 17};
        const run_context context{5, 1};

        evaluations_here = 0;
        const repetition_result alone = m->run(cell, context);
        const std::uint64_t alone_evaluations = evaluations_here;

        constexpr unsigned processes = 2;
        in_process_group group(processes);
        std::vector<process_outcome> outcome(processes);
        std::vector<std::thread> threads;
        for (unsigned r = 0; r < processes; ++r) {
          threads.emplace_back([&, r] {
            in_process_group::member exchange(group, r);
            const chunk_exchange_scope shared(&exchange);
            evaluations_here = 0;
            try {
              outcome[r].result = m->run(cell, context);
            } catch (const std::exception& e) {
              outcome[r].error = e.what();
            }
            outcome[r].evaluations = evaluations_here;
            outcome[r].windows_shared = exchange.windows_shared;
            outcome[r].chunks_whole = exchange.chunks_whole;
          });
        }
        for (std::thread& t : threads) t.join();

        std::uint64_t evaluations_between = 0;
        for (unsigned r = 0; r < processes; ++r) {
          const process_outcome& o = outcome[r];
          ASSERT_TRUE(o.error.empty()) << where << ", process " << r << ": " << o.error;
          EXPECT_TRUE(same_bits(o.result, alone)) << where << ", process " << r;
          evaluations_between += o.evaluations;
          if (m->shares_chunks_at(control)) {
            EXPECT_GT(o.windows_shared, 0u) << where << " declares it shares, but did not";
            EXPECT_EQ(o.chunks_whole, 0u) << where << " declares it shares, but ran "
                                          << o.chunks_whole << " chunks whole on process " << r;
            if (alone_evaluations > 0) {
              EXPECT_LT(o.evaluations, alone_evaluations) << where << ", process " << r;
            }
          } else {
            EXPECT_EQ(o.windows_shared, 0u) << where << " declares it does not share, but did";
            EXPECT_EQ(o.evaluations, alone_evaluations) << where << ", process " << r;
          }
        }
        if (m->shares_chunks_at(control)) {
          EXPECT_EQ(evaluations_between, alone_evaluations) << where;
        }
        covered.insert(where);
      }
    }
  }
  // Every method of the registry was run (a new method joins this test by being registered).
  for (const method_descriptor* d : method_registry()) {
    bool found = false;
    for (const std::string& w : covered) found = found || w.rfind(std::string(d->name), 0) == 0;
    EXPECT_TRUE(found) << d->name;
  }
}

// The declarations the planner relies on, as the kernels make them (the test above checks them
// against the kernels): the Smolyak tally and the adaptive methods stay on each process; every
// accumulator (the naive one by core/split_naive_sum.hpp) and every sample mean share.
TEST(MethodSharesChunks, SmolyakAndTheAdaptiveMethodsDoNotShare) {
  EXPECT_TRUE(make_method("midpoint")->shares_chunks());
  EXPECT_TRUE(make_method("midpoint", {{"accumulator", "long_double"}})->shares_chunks());
  EXPECT_TRUE(make_method("midpoint", {{"accumulator", "naive"}})->shares_chunks());
  EXPECT_FALSE(make_method("smolyak")->shares_chunks());
  EXPECT_FALSE(make_method("genz_malik")->shares_chunks());
  EXPECT_FALSE(make_method("vegas")->shares_chunks());
  EXPECT_FALSE(make_method("romberg")->shares_chunks());
  EXPECT_TRUE(make_method("plain_mc")->shares_chunks());
  EXPECT_TRUE(make_method("sobol", {{"randomization", "none"}})->shares_chunks());
}

}  // namespace
}  // namespace quadmc
