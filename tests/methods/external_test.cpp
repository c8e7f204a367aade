// Tests of the methods over point files (lib/src/methods/external.cpp): external_points on the
// CSV and .npy of the points the built-in `sobol` method would draw gives its estimate bitwise;
// external_rule on a tensor Simpson grid's nodes and weights gives `simpson` within the rounding
// bound of two summations; the options, sizes and error bars; the files checked before a run.
#include "method_error.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product_grid.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace quadmc {
namespace {

namespace fs = std::filesystem;
using test_support::temporary_directory;

// The CSV of `quadmc points` (bench/quadmc/points_command.cpp): a header x1,…,xs[,w], then each
// value as fmt's "{}", the shortest text that reads back to the same double.
void write_external_csv(const fs::path& file, std::size_t s, const std::vector<double>& x,
                        const std::vector<double>& w = {}) {
  std::string text;
  for (std::size_t j = 0; j < s; ++j) text += fmt::format("{}x{}", j == 0 ? "" : ",", j + 1);
  text += w.empty() ? "\n" : ",w\n";
  const std::size_t n = x.size() / s;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < s; ++j)
      text += fmt::format("{}{}", j == 0 ? "" : ",", x[i * s + j]);
    text += w.empty() ? "\n" : fmt::format(",{}\n", w[i]);
  }
  std::ofstream(file, std::ios::binary) << text;
}

// A float64 .npy, version 1.0, C order (x86-64 is little-endian, as '<f8' says).
void write_external_npy(const fs::path& file, std::size_t s, const std::vector<double>& x) {
  std::string header = fmt::format(
      "{{'descr': '<f8', 'fortran_order': False, 'shape': ({}, {}), }}", x.size() / s, s);
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  out += header;
  std::string data(x.size() * sizeof(double), '\0');
  std::memcpy(data.data(), x.data(), data.size());
  std::ofstream(file, std::ios::binary) << out << data;
}

std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

repetition_result run_external_cell(const method& m, const any_integrand& f,
                                    const integrand_params& p, const cell_size& size,
                                    std::uint64_t stream, std::uint64_t r, std::uint64_t seed) {
  const method_cell cell{f, p, size, cell_control::fixed_size, std::nan(""), stream, r};
  return m.run(cell, {seed, 2});
}

TEST(ExternalMethods, PointsOfTheBuiltInSobolGiveItsEstimateBitwiseFromCsvAndNpy) {
  const temporary_directory dir("external_sobol", temporary_directory::start::empty);
  constexpr std::size_t s = 3;
  constexpr std::uint64_t seed = 2026;
  integrand_params p;
  p.dimension = s;
  p.seed = 11;
  const any_integrand f = make_integrand("genz_gaussian", p);
  const auto sobol = make_method("sobol");  // randomization = "owen", its default
  const point_set_entry& set = *find_point_set("sobol");
  const std::string csv = (dir.path / "{N}_{r}.csv").string();
  const std::string npy = (dir.path / "{N}_{r}.npy").string();
  const auto from_csv = make_method("external_points", {{"path", csv}});
  const auto from_npy = make_method("external_points", {{"path", npy}});
  // 16384 points cross a chunk boundary of the sample mean (12288 points).
  for (const std::uint64_t N : {std::uint64_t{1024}, std::uint64_t{16384}}) {
    for (std::uint64_t r = 0; r < 3; ++r) {
      // The stream the runner gives repetition r of this cell (lib/src/scene/run.cpp:
      // stream_id(cell.stream_parts…, r), the parts {name_id(integrand), instance,
      // name_id(method label), nominal N} of lib/src/scene/plan.cpp), with the scene's seed.
      const std::uint64_t stream =
          stream_id({name_id("genz_gaussian_s3"), 0, name_id("sobol"), N, r});
      std::vector<double> x;
      // What `quadmc points sobol` writes for that (seed, stream): the set's points_over with
      // the method's options (the default randomization).
      set.points(
          s, N, {seed, stream},
          [&](std::uint64_t, std::span<const double> batch) {
            x.insert(x.end(), batch.begin(), batch.end());
          },
          point_set_options{});
      write_external_csv(dir.path / fmt::format("{}_{}.csv", N, r), s, x);
      write_external_npy(dir.path / fmt::format("{}_{}.npy", N, r), s, x);

      const cell_size size = *sobol->size_for(N, s).size;
      ASSERT_EQ(size.evaluations, N);
      const repetition_result built_in = run_external_cell(*sobol, f, p, size, stream, r, seed);
      const cell_size own = *from_csv->size_for(N, s).size;
      const repetition_result a = run_external_cell(*from_csv, f, p, own, 0, r, 0);
      const repetition_result b = run_external_cell(*from_npy, f, p, own, 0, r, 0);
      EXPECT_EQ(bits(a.value), bits(built_in.value)) << "N = " << N << ", r = " << r;
      EXPECT_EQ(bits(b.value), bits(built_in.value)) << "N = " << N << ", r = " << r;
      EXPECT_TRUE(std::isfinite(built_in.value));
      EXPECT_EQ(a.evaluations, N);
      EXPECT_TRUE(std::isnan(a.std_error)) << "one run of these points has no error of its own";
    }
  }
}

TEST(ExternalMethods, RuleOfATensorSimpsonGridGivesSimpsonWithinTheRoundingBound) {
  const temporary_directory dir("external_simpson", temporary_directory::start::empty);
  constexpr std::size_t s = 2;
  constexpr std::uint64_t n = 64;  // panels per axis: 65² = 4225 nodes
  integrand_params p;
  p.dimension = s;
  p.seed = 5;
  const any_integrand f = make_integrand("genz_gaussian", p);
  const tensor_product_grid grid(simpson_rule{}.nodes(n), s);
  const std::uint64_t N = grid.size();
  std::vector<double> x(N * s);
  std::vector<double> w(N);
  grid.generate(0, x, w);
  write_external_csv(dir.path / fmt::format("{}_0.csv", N), s, x, w);

  const auto simpson = make_method("simpson", {{"panels", static_cast<double>(n)}});
  const cell_size grid_size = *simpson->explicit_sizes(s)[0].size;
  ASSERT_EQ(grid_size.evaluations, N);
  const repetition_result q = run_external_cell(*simpson, f, p, grid_size, 0, 0, 0);
  const auto rule = make_method("external_rule", {{"path", (dir.path / "{N}_{r}.csv").string()}});
  const repetition_result e = run_external_cell(*rule, f, p, *rule->size_for(N, s).size, 0, 0, 0);

  // Bound: both are vol·Σ w_i f(x_i) over the same doubles w_i, x_i (fmt's "{}" reads back
  // bitwise) and the same f values. Any order of summing N rounded products errs by at most
  // (N − 1)·u·Σ|w f| plus u·Σ|w f| for the products (u = 2^−53, first order; [Higham 2002, §4.2]),
  // so two orders differ by at most 2·N·u·vol·Σ|w_i f(x_i)|.
  const box& domain = f.info().domain;
  std::vector<double> mapped = x;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      mapped[i * s + j] = domain.lower[j] + (domain.upper[j] - domain.lower[j]) * x[i * s + j];
    }
  }
  std::vector<double> y(N);
  f.evaluate(mapped, y);
  double abs_terms = 0.0;
  for (std::size_t i = 0; i < N; ++i) abs_terms += std::abs(w[i] * y[i]);
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double bound = 2.0 * static_cast<double>(N) * u * domain.volume() * abs_terms;
  EXPECT_LE(std::abs(e.value - q.value), bound) << e.value << " vs " << q.value;
  RecordProperty("simpson", fmt::format("{:.17g}", q.value));
  RecordProperty("external_rule", fmt::format("{:.17g}", e.value));
  RecordProperty("rounding_bound", fmt::format("{:.3g}", bound));
  EXPECT_EQ(e.evaluations, N);
  double abs_w = 0.0;
  for (const double v : w) abs_w += std::abs(v);
  EXPECT_NEAR(e.absolute_weight_sum, abs_w, 1e-12 * abs_w) << "Σ|w| for the rounding floor";
  // The same order as simpson's own (the file's rows are the grid's index order through the one
  // weighted-sum kernel): in fact the same bits.
  EXPECT_EQ(bits(e.value), bits(q.value));
}

TEST(ExternalMethods, KeysSizesAndErrorBars) {
  EXPECT_NE(error_of("external_points", {}).find("path"), std::string::npos);
  EXPECT_NE(error_of("external_points", {{"path", "a/{N}.csv"}}).find("{r}"), std::string::npos);
  EXPECT_NE(error_of("external_rule", {{"path", "a/{r}.csv"}}).find("{N}"), std::string::npos);
  EXPECT_NE(error_of("external_points",
                     {{"path", "{N}_{r}.csv"}, {"points", std::vector<double>{64, 32}}})
                .find("increase"),
            std::string::npos);
  const auto m = make_method("external_points",
                             {{"path", "{N}_{r}.csv"}, {"points", std::vector<double>{10, 300}}});
  EXPECT_EQ(m->kind(), method_kind::randomized);
  EXPECT_EQ(m->error_bars(), error_bars::replicates);
  EXPECT_EQ(m->explicit_sizes_key(), "points");
  ASSERT_EQ(m->explicit_sizes(2).size(), 2u);
  EXPECT_EQ(m->explicit_sizes(2)[1].size->evaluations, 300u);
  EXPECT_EQ(m->size_for(1000, 3).size->evaluations, 1000u) << "N is the file's size, not mapped";
}

TEST(ExternalMethods, CheckInputsReadsEveryRepetitionsFileBeforeAnyRun) {
  const temporary_directory dir("external_check", temporary_directory::start::empty);
  const auto m = make_method("external_points", {{"path", (dir.path / "{N}_{r}.csv").string()}});
  write_external_csv(dir.path / "2_0.csv", 1, {0.25, 0.75});
  write_external_csv(dir.path / "2_1.csv", 1, {0.25, 0.5, 0.75});
  const cell_size size = *m->size_for(2, 1).size;
  EXPECT_NO_THROW(m->check_inputs(1, size, 1));
  try {
    m->check_inputs(1, size, 3);
    ADD_FAILURE() << "a file of 3 rows for N = 2 was accepted";
  } catch (const invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("2_1.csv"), std::string::npos) << message;
    EXPECT_NE(message.find("N = 2 rows"), std::string::npos) << message;
  }
  write_external_csv(dir.path / "2_1.csv", 1, {0.25, 0.5});
  EXPECT_THROW(m->check_inputs(1, size, 3), invalid_argument) << "2_2.csv is missing";
  EXPECT_THROW(m->check_inputs(2, size, 1), invalid_argument) << "s = 2, the file has 1 column";
}

}  // namespace
}  // namespace quadmc
