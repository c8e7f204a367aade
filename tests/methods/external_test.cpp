// Tests of the methods over point files (lib/src/methods/external.cpp): external_points on the
// CSV and .npy of the points the built-in `sobol` method would draw gives its estimate bitwise;
// external_rule on a tensor Simpson grid's nodes and weights gives `simpson` within the rounding
// bound of two summations; the options, sizes and error bars; the files checked before a run.
// The same files as the uniforms of importance and the irradiance methods (point_set =
// "external_points"): the bits of their `sobol` point set, the column count each needs, the keys
// that belong to the files only.
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

// The points `quadmc points sobol` writes for (seed, stream), in s dimensions, as the CSV and the
// .npy of the template "{N}_{r}" in `dir`.
void write_sobol_files(const fs::path& dir, std::size_t s, std::uint64_t N, std::uint64_t r,
                       const sample_stream& stream) {
  std::vector<double> x;
  find_point_set("sobol")->points(
      s, N, stream,
      [&](std::uint64_t, std::span<const double> batch) {
        x.insert(x.end(), batch.begin(), batch.end());
      },
      point_set_options{});
  write_external_csv(dir / fmt::format("{}_{}.csv", N, r), s, x);
  write_external_npy(dir / fmt::format("{}_{}.npy", N, r), s, x);
}

// Runs `built_in` (point_set = "sobol") at the stream the runner gives repetition r of its cell
// and the two file-fed methods on the files of those points, and compares the bits.
void expect_sobol_bits(const method& built_in, const method& from_csv, const method& from_npy,
                       const fs::path& dir, const any_integrand& f, const integrand_params& p,
                       std::size_t uniforms, std::string_view where) {
  constexpr std::uint64_t seed = 2026;
  // 16384 samples cross a chunk boundary of the sample mean (12288 samples).
  for (const std::uint64_t N : {std::uint64_t{1024}, std::uint64_t{16384}}) {
    for (std::uint64_t r = 0; r < 3; ++r) {
      // lib/src/scene/run.cpp's stream_id(cell.stream_parts…, r), as in the test above.
      const std::uint64_t stream =
          stream_id({name_id(f.info().name), 0, name_id(built_in.descriptor().name), N, r});
      write_sobol_files(dir, uniforms, N, r, {seed, stream});
      const cell_size size = *built_in.size_for(N, f.dimension()).size;
      ASSERT_EQ(size.evaluations, N) << where;
      const repetition_result sobol = run_external_cell(built_in, f, p, size, stream, r, seed);
      const cell_size own = *from_csv.size_for(N, f.dimension()).size;
      const repetition_result a = run_external_cell(from_csv, f, p, own, 0, r, 0);
      const repetition_result b = run_external_cell(from_npy, f, p, own, 0, r, 0);
      EXPECT_TRUE(std::isfinite(sobol.value)) << where;
      EXPECT_EQ(bits(a.value), bits(sobol.value)) << where << ", N = " << N << ", r = " << r;
      EXPECT_EQ(bits(b.value), bits(sobol.value)) << where << ", N = " << N << ", r = " << r;
      EXPECT_EQ(a.evaluations, N) << where;
    }
  }
}

option_table file_uniforms(option_table options, const fs::path& file_template) {
  options.insert_or_assign("point_set", "external_points");
  options.insert_or_assign("path", file_template.string());
  return options;
}

TEST(ExternalPointSet, ImportanceOnSobolFilesGivesImportanceWithSobolBitwise) {
  const temporary_directory dir("external_importance", temporary_directory::start::empty);
  integrand_params p;
  p.dimension = 1;
  const any_integrand f = make_integrand("exp", p);
  for (const char* warp : {"power", "exponential"}) {
    const option_table options{{"warp", warp}};
    option_table sobol = options;
    sobol.insert_or_assign("point_set", "sobol");
    const auto built_in = make_method("importance", sobol);
    const auto from_csv =
        make_method("importance", file_uniforms(options, dir.path / "{N}_{r}.csv"));
    const auto from_npy =
        make_method("importance", file_uniforms(options, dir.path / "{N}_{r}.npy"));
    expect_sobol_bits(*built_in, *from_csv, *from_npy, dir.path, f, p, 1,
                      std::string("importance, warp ") + warp);
  }
}

TEST(ExternalPointSet, IrradianceOnSobolFilesGivesIrradianceWithSobolBitwise) {
  const temporary_directory dir("external_irradiance", temporary_directory::start::empty);
  integrand_params p;
  p.dimension = 2;
  p.scalars["occluder"] = 1.0;  // the visibility test too
  const any_integrand f = make_integrand("irradiance_area", p);
  for (const char* name : {"irradiance_light_area", "irradiance_hemisphere_cosine"}) {
    const auto built_in = make_method(name, {{"point_set", "sobol"}});
    const auto from_csv = make_method(name, file_uniforms({}, dir.path / "{N}_{r}.csv"));
    const auto from_npy = make_method(name, file_uniforms({}, dir.path / "{N}_{r}.npy"));
    expect_sobol_bits(*built_in, *from_csv, *from_npy, dir.path, f, p, 2, name);
  }
}

// check_inputs' message for a cell of N = 4 over one repetition, or "no error".
std::string check_error(const method& m, std::size_t s) {
  try {
    m.check_inputs(s, *m.size_for(4, s).size, 1);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(ExternalPointSet, AFileOfTheWrongColumnCountIsRefusedBeforeAnyRun) {
  const temporary_directory dir("external_columns", temporary_directory::start::empty);
  write_external_csv(dir.path / "4_0.csv", 1, {0.125, 0.375, 0.625, 0.875});
  write_external_csv(dir.path / "two_4_0.csv", 2, {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8});
  const auto importance_1d =
      make_method("importance", file_uniforms({{"warp", "power"}}, dir.path / "{N}_{r}.csv"));
  const auto importance_2d =
      make_method("importance", file_uniforms({{"warp", "power"}}, dir.path / "two_{N}_{r}.csv"));
  const auto light_1d =
      make_method("irradiance_light_area", file_uniforms({}, dir.path / "{N}_{r}.csv"));
  const auto light_2d =
      make_method("irradiance_light_area", file_uniforms({}, dir.path / "two_{N}_{r}.csv"));
  EXPECT_EQ(check_error(*importance_1d, 1), "no error");
  EXPECT_EQ(check_error(*light_2d, 2), "no error");

  const std::string importance = check_error(*importance_2d, 1);
  EXPECT_NE(importance.find("two_4_0.csv = 2 columns: expected 1 (importance"), std::string::npos)
      << importance;
  EXPECT_NE(importance.find("point_set = \"external_points\" needs s = 1"), std::string::npos)
      << importance;
  const std::string light = check_error(*light_1d, 2);
  EXPECT_NE(light.find("4_0.csv = 1 columns: expected 2 (irradiance_light_area"), std::string::npos)
      << light;
  EXPECT_NE(light.find("needs s = 2"), std::string::npos) << light;
  for (const std::string& m : {importance, light}) {
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
  }
}

TEST(ExternalPointSet, FileKeysBelongToTheExternalPointSetOnly) {
  const option_table power{{"warp", "power"}};
  option_table with_path = power;
  with_path.insert_or_assign("path", "{N}_{r}.csv");
  const std::string no_set = error_of("importance", with_path);
  EXPECT_NE(no_set.find(".path: "), std::string::npos) << no_set;
  EXPECT_NE(no_set.find("expected only with point_set = \"external_points\""), std::string::npos)
      << no_set;
  EXPECT_NE(no_set.find("got it with no point_set"), std::string::npos) << no_set;
  with_path.insert_or_assign("point_set", "sobol");
  EXPECT_NE(error_of("importance", with_path).find("got it with point_set = \"sobol\""),
            std::string::npos);
  const std::string points =
      error_of("irradiance_hemisphere_uniform", {{"points", std::vector<double>{16, 32}}});
  EXPECT_NE(points.find(".points: "), std::string::npos) << points;
  EXPECT_NE(points.find("expected only with point_set"), std::string::npos) << points;
  // The reverse: the files' set without its files.
  const std::string no_path = error_of("irradiance_light_area", {{"point_set", "external_points"}});
  EXPECT_NE(no_path.find("path"), std::string::npos) << no_path;
  EXPECT_NE(error_of("importance", file_uniforms(power, "{N}.csv")).find("without {r}"),
            std::string::npos);
}

TEST(ExternalPointSet, SizesErrorBarsAndLabelsAreThoseOfTheFiles) {
  option_table options = file_uniforms({{"warp", "exponential"}}, "{N}_{r}.csv");
  options.insert_or_assign("points", std::vector<double>{10, 300});
  const auto m = make_method("importance", options);
  EXPECT_EQ(m->label_suffix(), "_exponential_external_points");
  EXPECT_EQ(m->kind(), method_kind::randomized);
  EXPECT_EQ(m->error_bars(), error_bars::replicates);
  EXPECT_EQ(m->explicit_sizes_key(), "points");
  ASSERT_EQ(m->explicit_sizes(1).size(), 2u);
  EXPECT_EQ(m->explicit_sizes(1)[1].size->evaluations, 300u);
  EXPECT_EQ(m->size_for(1000, 1).size->evaluations, 1000u) << "N is the file's size, not mapped";
  EXPECT_FALSE(m->theory({smoothness::smooth, 1, std::nan("")}).slope.has_value());
  const auto light = make_method("irradiance_light_area", file_uniforms({}, "{N}_{r}.csv"));
  EXPECT_EQ(light->label_suffix(), "_external_points");
  EXPECT_EQ(light->error_bars(), error_bars::replicates);
  EXPECT_TRUE(light->explicit_sizes(2).empty()) << "without points, the cells follow budget.N";
  EXPECT_EQ(light->size_for(1000, 2).size->evaluations, 1000u);
}

}  // namespace
}  // namespace quadmc
