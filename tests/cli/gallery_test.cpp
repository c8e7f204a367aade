// End-to-end tests of `quadmc gallery` (bench/quadmc/gallery_command.hpp): the plan printed
// before the work, every file of the folder, exactly one point per stratum wherever the gallery
// draws a stratum grid, the same bytes for the same seed, a second run replacing the first, and
// one-line errors for bad arguments and a folder the gallery may not replace. For --points: the
// suite's own Sobol' points written to files give the sobol row's numbers bitwise, the
// realizations are counted and said, and a bad file or NAME is refused in one line, writing
// nothing.
#include "quadmc/report/csv.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace quadmc_cli_test {
namespace {

const std::vector<std::string> gallery_files{"README.md",    "discrepancy.csv", "gallery.png",
                                             "meta.csv",     "scatter.csv",     "spectra.png",
                                             "spectrum.csv", "strata.csv"};

// One gallery with few realizations, shared by the tests that only read it.
class GalleryCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<scratch_folder>();
    result_ = std::make_unique<command_result>(run_quadmc(
        *dir_, {"gallery", "--out", "g", "--realizations", "3", "--seed", "5", "--threads", "3"}));
  }
  static void TearDownTestSuite() {
    result_.reset();
    dir_.reset();
  }
  static quadmc::csv_table table(const std::string& name) {
    return quadmc::parse_csv(read_text(*dir_ / "g" / name), name);
  }
  static std::unique_ptr<scratch_folder> dir_;
  static std::unique_ptr<command_result> result_;
};
std::unique_ptr<scratch_folder> GalleryCommand::dir_;
std::unique_ptr<command_result> GalleryCommand::result_;

TEST_F(GalleryCommand, PrintsThePlanFirstAndWritesEveryFile) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  EXPECT_EQ(result_->out.rfind("gallery: 12 point sets in s = 2 (seed 5), 3 threads", 0), 0u)
      << describe(*result_);
  EXPECT_NE(result_->out.find("over 3 realizations per set"), std::string::npos);
  EXPECT_NE(result_->out.find("jittered         strata: N = 16: 4 × 4 cells"), std::string::npos)
      << result_->out;
  EXPECT_NE(result_->out.find("\ngallery: 12 point sets in "), std::string::npos);
  EXPECT_NE(result_->out.find("wrote "), std::string::npos);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(*dir_ / "g")) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, gallery_files);
  const std::string readme = read_text(*dir_ / "g" / "README.md");
  EXPECT_NE(readme.find("![Scatter plots"), std::string::npos);
  EXPECT_NE(readme.find("3 realizations"), std::string::npos);
  const quadmc::csv_table spectrum = table("spectrum.csv");
  std::set<std::string> sets;
  for (const auto& row : spectrum.rows) {
    sets.insert(row[spectrum.column("set")]);
    EXPECT_EQ(row[spectrum.column("realizations")], "3");
    EXPECT_EQ(row[spectrum.column("n")], "1024");
  }
  EXPECT_EQ(sets.size(), 12u);  // the catalogue's 11 and zsobol's tile
  EXPECT_EQ(spectrum.rows.size(), 12u * 64u);
}

// discrepancy.csv's t-values (sampling/net_quality.hpp): the scrambled nets of every size are
// (0, m, 2)-nets; the randomly shifted k × k grid of centres, k = 2^(m/2), has t = m/2 exactly
// (a dyadic box no thinner than a cell holds its share of the columns and rows of any shifted
// grid; a thinner one misses some); every set reports a positive minimum distance (it may exceed
// the packing's at small N, where the square's sides leave room: 16 points can be 1/3 apart).
TEST_F(GalleryCommand, NetsHaveTZeroAndShiftedGridsHalfOfM) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  const quadmc::csv_table d = table("discrepancy.csv");
  int checked = 0;
  for (const auto& row : d.rows) {
    const std::string set = row[d.column("set")];
    const auto n = std::stoull(row[d.column("n")]);
    const std::string t = row[d.column("t_value_max")];
    // zsobol's row is a 2 × 2 tile of pixels, N/4 points each: together one scrambled net.
    if (set == "sobol" || set == "padded_sobol" || set == "pmj02" || set == "zsobol") {
      EXPECT_EQ(t, "0") << set << " N = " << n;
      ++checked;
    } else if (set == "unjittered") {
      EXPECT_EQ(t, std::to_string(std::countr_zero(n) / 2)) << "N = " << n;
      ++checked;
    }
    const double delta = std::stod(row[d.column("min_distance_ratio_mean")]);
    EXPECT_GT(delta, 0.0) << set << " N = " << n;
    EXPECT_TRUE(std::isfinite(delta)) << set << " N = " << n;
  }
  EXPECT_EQ(checked, 20);
}

// Every grid strata.csv lists is checked against the points of scatter.csv: `cells` means each
// of the columns × rows cells holds exactly one point, `rows_and_columns` each of the N columns
// and each of the N rows of width 1/N. The stratified sets must list their grids at every N, so
// the check cannot pass by listing none.
TEST_F(GalleryCommand, StratifiedSetsPutExactlyOnePointPerStratum) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  const quadmc::csv_table scatter = table("scatter.csv");
  std::map<std::pair<std::string, std::string>, std::vector<std::pair<double, double>>> points;
  for (const auto& row : scatter.rows) {
    points[{row[scatter.column("set")], row[scatter.column("n")]}].emplace_back(
        std::stod(row[scatter.column("x1")]), std::stod(row[scatter.column("x2")]));
  }
  const quadmc::csv_table strata = table("strata.csv");
  std::set<std::pair<std::string, std::string>> listed;
  for (const auto& row : strata.rows) {
    const std::string set = row[strata.column("set")];
    const std::string n = row[strata.column("n")];
    listed.insert({set, row[strata.column("kind")] + "@" + n});
    const auto& x = points.at({set, n});
    ASSERT_EQ(x.size(), std::stoul(n)) << set;
    const auto columns = std::stoul(row[strata.column("columns")]);
    const auto rows = std::stoul(row[strata.column("rows")]);
    auto cell = [](double t, unsigned long k) {
      return std::min(k - 1, static_cast<unsigned long>(std::floor(t * static_cast<double>(k))));
    };
    if (row[strata.column("kind")] == "cells") {
      ASSERT_EQ(columns * rows, x.size()) << set << " N = " << n;
      std::set<std::pair<unsigned long, unsigned long>> cells;
      for (const auto& [a, b] : x) cells.insert({cell(a, columns), cell(b, rows)});
      EXPECT_EQ(cells.size(), x.size()) << set << " N = " << n << ": a cell holds two points";
    } else {
      ASSERT_EQ(row[strata.column("kind")], "rows_and_columns");
      std::set<unsigned long> xs, ys;
      for (const auto& [a, b] : x) {
        xs.insert(cell(a, columns));
        ys.insert(cell(b, rows));
      }
      EXPECT_EQ(xs.size(), x.size()) << set << " N = " << n << ": a column holds two points";
      EXPECT_EQ(ys.size(), x.size()) << set << " N = " << n << ": a row holds two points";
    }
  }
  for (const std::string n : {"16", "64", "256"}) {
    for (const std::string set : {"jittered", "unjittered", "padded_jittered", "sobol", "zsobol"}) {
      EXPECT_TRUE(listed.count({set, "cells@" + n})) << set << " N = " << n;
    }
    for (const std::string set : {"latin_hypercube", "lattice"}) {
      EXPECT_TRUE(listed.count({set, "rows_and_columns@" + n})) << set << " N = " << n;
    }
  }
}

TEST_F(GalleryCommand, SameSeedGivesTheSameNumbersOnAnyThreadCountAndReplacesItsOwnFolder) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  // On one thread instead of all cores (the fixture's run): the same bytes.
  const command_result again = run_quadmc(
      *dir_, {"gallery", "--out", "g2", "--realizations", "3", "--seed", "5", "--threads", "1"});
  ASSERT_EQ(again.exit_status, 0) << describe(again);
  for (const std::string file : {"scatter.csv", "spectrum.csv", "discrepancy.csv", "strata.csv"}) {
    EXPECT_EQ(read_text(*dir_ / "g2" / file), read_text(*dir_ / "g" / file)) << file;
  }
  // A second gallery into a folder of the first replaces it (its files are the gallery's own).
  const command_result replaced =
      run_quadmc(*dir_, {"gallery", "--out", "g2", "--realizations", "2", "--seed", "6"});
  ASSERT_EQ(replaced.exit_status, 0) << describe(replaced);
  EXPECT_NE(read_text(*dir_ / "g2" / "scatter.csv"), read_text(*dir_ / "g" / "scatter.csv"));
}

void expect_gallery_error(const std::vector<std::string>& args, int status,
                          const std::string& names) {
  scratch_folder dir;
  write_text(dir / "mine.txt", "keep me");
  fs::create_directory(dir / "notes");
  write_text(dir / "notes" / "todo.txt", "keep me too");
  const command_result r = run_quadmc(dir, args);
  EXPECT_EQ(r.exit_status, status) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find(names), std::string::npos) << describe(r);
  EXPECT_TRUE(r.out.empty()) << describe(r);
  EXPECT_EQ(read_text(dir / "notes" / "todo.txt"), "keep me too");
  EXPECT_FALSE(fs::exists(dir / "results"));
}

TEST(GalleryErrors, BadArgumentsGetOneLine) {
  expect_gallery_error({"gallery", "--realizations", "1"}, 2, "--realizations");
  expect_gallery_error({"gallery", "--realizations", "many"}, 2, "--realizations");
  expect_gallery_error({"gallery", "--realizations", "100001"}, 2, "--realizations");
  expect_gallery_error(
      {"gallery", "--seed", "-3"}, 2,
      "--seed: expected an integer K with 0 ≤ K ≤ 2^64 − 1 = 18446744073709551615, got -3");
  expect_gallery_error({"gallery", "--threads", "5000"}, 2, "--threads");
  expect_gallery_error({"gallery", "extra"}, 2, "extra");
  expect_gallery_error({"gallery", "--out"}, 2, "--out");
}

TEST(GalleryErrors, RefusesAFolderThatIsNotItsOwn) {
  // A folder with somebody's file in it is not replaced, before anything is computed.
  expect_gallery_error({"gallery", "--out", "notes", "--realizations", "2"}, 1,
                       "--out 'notes': not a results folder: it holds 'todo.txt'");
  // A `run` results folder is not the gallery's either (convergence.csv is not a gallery file).
  scratch_folder dir;
  fs::create_directory(dir / "r");
  write_text(dir / "r" / "convergence.csv", "x\n");
  const command_result r = run_quadmc(dir, {"gallery", "--out", "r", "--realizations", "2"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_NE(r.err.find("it holds 'convergence.csv'"), std::string::npos) << describe(r);
  EXPECT_EQ(read_text(dir / "r" / "convergence.csv"), "x\n");
}

// The rows of `file` whose `set` is `name`, without that column: what the set's numbers are.
std::vector<std::vector<std::string>> rows_of(const fs::path& file, const std::string& name) {
  const quadmc::csv_table t = quadmc::parse_csv(read_text(file), file.string());
  std::vector<std::vector<std::string>> out;
  for (auto row : t.rows) {
    if (row[t.column("set")] != name) continue;
    row.erase(row.begin() + static_cast<std::ptrdiff_t>(t.column("set")));
    out.push_back(row);
  }
  return out;
}

// The suite's Sobol' points of seed 5, streams 0 … 3, written by `quadmc points` to pts/N_r.csv at
// every size the gallery uses: the gallery draws its sobol row from the same (seed, stream), so a
// user's row over these files must carry the same numbers, bit for bit (`quadmc points` writes
// the shortest decimal that reads back to the same double).
class GalleryPoints : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<scratch_folder>();
    fs::create_directory(*dir_ / "pts");
    for (const std::string n : {"16", "64", "256", "1024"}) {
      for (const std::string r : {"0", "1", "2", "3"}) {
        const command_result w =
            run_quadmc(*dir_, {"points", "sobol", "--n", n, "--s", "2", "--seed", "5", "--stream",
                               r, "--out", "pts/" + n + "_" + r + ".csv"});
        ASSERT_EQ(w.exit_status, 0) << describe(w);
      }
    }
  }
  static void TearDownTestSuite() { dir_.reset(); }
  static std::unique_ptr<scratch_folder> dir_;
};
std::unique_ptr<scratch_folder> GalleryPoints::dir_;

TEST_F(GalleryPoints, SobolFilesGiveTheSobolRowBitwiseOnAnyThreadCount) {
  const std::vector<std::string> args{"gallery",  "--realizations",      "4", "--seed", "5",
                                      "--points", "mine=pts/{N}_{r}.csv"};
  std::vector<std::string> three = args;
  three.insert(three.end(), {"--out", "g", "--threads", "3"});
  const command_result r = run_quadmc(*dir_, three);
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.out.rfind("gallery: 12 point sets and 1 from files (--points) in s = 2", 0), 0u)
      << r.out;
  EXPECT_NE(r.out.find("mine             strata: none (files pts/{N}_{r}.csv; realizations at "
                       "N = 16, 64, 256, 1024: 4, 4, 4, 4)"),
            std::string::npos)
      << r.out;
  const fs::path g = *dir_ / "g";
  for (const std::string file : {"discrepancy.csv", "spectrum.csv", "scatter.csv"}) {
    const auto mine = rows_of(g / file, "mine");
    ASSERT_FALSE(mine.empty()) << file;
    EXPECT_EQ(mine, rows_of(g / file, "sobol")) << file;
  }
  EXPECT_TRUE(rows_of(g / "strata.csv", "mine").empty());
  // The user's rows come after the suite's: the last rows of every table.
  const quadmc::csv_table spectrum = quadmc::parse_csv(read_text(g / "spectrum.csv"), "spectrum");
  EXPECT_EQ(spectrum.rows.back()[spectrum.column("set")], "mine");
  EXPECT_EQ(rows_of(g / "user_points.csv", "mine"),
            (std::vector<std::vector<std::string>>{{"pts/{N}_{r}.csv", "16", "4"},
                                                   {"pts/{N}_{r}.csv", "64", "4"},
                                                   {"pts/{N}_{r}.csv", "256", "4"},
                                                   {"pts/{N}_{r}.csv", "1024", "4"}}));
  const std::string readme = read_text(g / "README.md");
  EXPECT_NE(readme.find("## Your point sets (--points)"), std::string::npos);
  EXPECT_NE(readme.find("| mine | `pts/{N}_{r}.csv` | 4 | 4 | 4 | 4 |"), std::string::npos);
  EXPECT_NE(readme.find("| mine *(--points)* |"), std::string::npos);
  EXPECT_TRUE(fs::exists(g / "gallery.png"));
  // One thread instead of three: the same bytes, the user's rows included.
  std::vector<std::string> one = args;
  one.insert(one.end(), {"--out", "g1", "--threads", "1"});
  const command_result again = run_quadmc(*dir_, one);
  ASSERT_EQ(again.exit_status, 0) << describe(again);
  for (const std::string file :
       {"scatter.csv", "spectrum.csv", "discrepancy.csv", "strata.csv", "user_points.csv"}) {
    EXPECT_EQ(read_text(*dir_ / "g1" / file), read_text(g / file)) << file;
  }
}

// The points of a CSV file as `quadmc points` writes it, as a .npy float64 array of shape (N, 2)
// (format 1.0: magic, version, header length, then the header padded with spaces to a multiple of
// 64 bytes and ended by '\n', as numpy/lib/format.py writes it). Little-endian, as x86-64 is.
void write_npy_of(const fs::path& csv, const fs::path& npy) {
  const quadmc::csv_table t = quadmc::parse_csv(read_text(csv), csv.string());
  std::string data;
  for (const auto& row : t.rows) {
    for (const std::string& field : row) {
      const double v = std::stod(field);  // correctly rounded: the shortest text reads back
      char bytes[sizeof v];
      std::memcpy(bytes, &v, sizeof v);
      data.append(bytes, sizeof v);
    }
  }
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" +
                       std::to_string(t.rows.size()) + ", 2), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  write_text(npy, out + header + data);
}

// Fewer files than R: the realizations are r = 0, 1, … up to the first missing file, per N, and a
// template without {r} is one realization; every table says how many each row averages.
TEST_F(GalleryPoints, CountsTheRealizationsThereAreAndSaysSo) {
  fs::create_directory(*dir_ / "few");
  for (const std::string n : {"16", "64", "256", "1024"}) {
    fs::copy_file(*dir_ / "pts" / (n + "_0.csv"), *dir_ / "few" / (n + "_0.csv"),
                  fs::copy_options::overwrite_existing);
  }
  fs::copy_file(*dir_ / "pts" / "1024_1.csv", *dir_ / "few" / "1024_1.csv",
                fs::copy_options::overwrite_existing);
  // r = 3 beyond the gap at r = 2 is not counted.
  fs::copy_file(*dir_ / "pts" / "1024_3.csv", *dir_ / "few" / "1024_3.csv",
                fs::copy_options::overwrite_existing);
  fs::create_directory(*dir_ / "npy");
  for (const std::string n : {"16", "64", "256", "1024"}) {
    write_npy_of(*dir_ / "pts" / (n + "_0.csv"), *dir_ / "npy" / (n + ".npy"));
  }
  const command_result r = run_quadmc(
      *dir_, {"gallery", "--out", "gf", "--realizations", "4", "--seed", "5", "--points",
              "few=few/{N}_{r}.csv", "--points", "one=" + (*dir_ / "pts").string() + "/{N}_0.csv",
              "--points", "npy=npy/{N}.npy"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  const fs::path g = *dir_ / "gf";
  const quadmc::csv_table d = quadmc::parse_csv(read_text(g / "discrepancy.csv"), "discrepancy");
  std::map<std::string, std::vector<std::string>> realizations;
  for (const auto& row : d.rows) {
    realizations[row[d.column("set")]].push_back(row[d.column("realizations")]);
  }
  EXPECT_EQ(realizations["few"], (std::vector<std::string>{"1", "1", "1", "2"}));
  EXPECT_EQ(realizations["one"], (std::vector<std::string>{"1", "1", "1", "1"}));
  EXPECT_EQ(realizations["sobol"], (std::vector<std::string>{"4", "4", "4", "4"}));
  const quadmc::csv_table s = quadmc::parse_csv(read_text(g / "spectrum.csv"), "spectrum");
  std::map<std::string, std::set<std::string>> spectrum;
  for (const auto& row : s.rows) {
    spectrum[row[s.column("set")]].insert(row[s.column("realizations")]);
  }
  EXPECT_EQ(spectrum["few"], (std::set<std::string>{"2"}));
  EXPECT_EQ(spectrum["one"], (std::set<std::string>{"1"}));
  EXPECT_EQ(spectrum["sobol"], (std::set<std::string>{"4"}));
  // The pictured points (r = 0) are the sobol row's, whatever the realizations; the same points
  // as .npy give the same numbers as the CSV.
  EXPECT_EQ(rows_of(g / "scatter.csv", "one"), rows_of(g / "scatter.csv", "sobol"));
  EXPECT_EQ(rows_of(g / "scatter.csv", "npy"), rows_of(g / "scatter.csv", "sobol"));
  EXPECT_EQ(rows_of(g / "discrepancy.csv", "npy"), rows_of(g / "discrepancy.csv", "one"));
  EXPECT_EQ(rows_of(g / "spectrum.csv", "npy"), rows_of(g / "spectrum.csv", "one"));
  const std::string readme = read_text(g / "README.md");
  EXPECT_NE(readme.find("| few | `few/{N}_{r}.csv` | 1 | 1 | 1 | 2 |"), std::string::npos)
      << readme;
}

// Points ((i + ½)/N, (7i mod N + ½)/N): a valid s = 2 file of N rows, as CSV with its header.
std::string grid_csv(unsigned n, unsigned s = 2) {
  std::ostringstream out;
  out << "x1,x2" << (s == 3 ? ",x3" : "") << "\n";
  for (unsigned i = 0; i < n; ++i) {
    out << (i + 0.5) / n << "," << ((7 * i) % n + 0.5) / n << (s == 3 ? ",0.5" : "") << "\n";
  }
  return out.str();
}

// Writes every file pts/N_0.csv of the gallery's sizes into `dir`, then lets `spoil` break one,
// runs the gallery with --points and expects a one-line refusal that names `names` and wrote
// nothing: no folder, no plan.
template <typename Spoil>
void expect_refused_points(Spoil spoil, const std::string& value, int status,
                           const std::string& names) {
  scratch_folder dir;
  fs::create_directory(dir / "pts");
  for (const unsigned n : {16u, 64u, 256u, 1024u}) {
    write_text(dir / "pts" / (std::to_string(n) + "_0.csv"), grid_csv(n));
  }
  spoil(dir);
  const command_result r =
      run_quadmc(dir, {"gallery", "--out", "g", "--realizations", "2", "--points", value});
  EXPECT_EQ(r.exit_status, status) << value << "\n" << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find(names), std::string::npos) << describe(r);
  EXPECT_TRUE(r.out.empty()) << describe(r);
  EXPECT_FALSE(fs::exists(dir / "g"));
  EXPECT_FALSE(fs::exists(dir / "results"));
}

TEST(GalleryPointsErrors, ABadFileIsRefusedNamingItBeforeAnyWork) {
  const std::string value = "mine=pts/{N}_{r}.csv";
  const auto remove_256 = [](const scratch_folder& d) { fs::remove(d / "pts" / "256_0.csv"); };
  expect_refused_points(remove_256, value, 1,
                        "--points mine=pts/{N}_{r}.csv: invalid point file pts/256_0.csv = "
                        "missing");
  const auto three_columns = [](const scratch_folder& d) {
    write_text(d / "pts" / "64_0.csv", grid_csv(64, 3));
  };
  expect_refused_points(three_columns, value, 1, "pts/64_0.csv = 3 columns: expected 2");
  const auto one_is_out = [](const scratch_folder& d) {
    std::string text = grid_csv(16);
    text.replace(text.find("\n0.09375,") + 1, 7, "1.00000");  // row 2: x1 = 1 is outside [0, 1)
    write_text(d / "pts" / "16_0.csv", text);
  };
  expect_refused_points(one_is_out, value, 1,
                        "pts/16_0.csv row 2 column 1 = 1.00000: expected a coordinate in [0, 1)");
  // A realization r > 0 that exists is checked as r = 0 is: here it has the wrong N.
  const auto bad_second = [](const scratch_folder& d) {
    write_text(d / "pts" / "1024_1.csv", grid_csv(1000));
  };
  expect_refused_points(bad_second, value, 1, "pts/1024_1.csv = 1000 rows: expected N = 1024");
}

TEST(GalleryPointsErrors, ABadNameOrTemplateIsAUsageError) {
  const auto none = [](const scratch_folder&) {};
  expect_refused_points(none, "sobol=pts/{N}_{r}.csv", 2,
                        "--points: expected NAME=PATH_TEMPLATE (e.g. mine=pts/{N}_{r}.csv), got "
                        "'sobol=pts/{N}_{r}.csv': NAME is a point set of the suite");
  expect_refused_points(none, "a,b=pts/{N}_{r}.csv", 2,
                        "got 'a,b=pts/{N}_{r}.csv': NAME must be 1 to 40 letters");
  expect_refused_points(none, "=pts/{N}_{r}.csv", 2, "--points: expected NAME=PATH_TEMPLATE");
  expect_refused_points(none, "mine", 2, "got 'mine': no '='");
  expect_refused_points(none, "mine=pts/16_0.csv", 2, "PATH_TEMPLATE needs {N}");
  // The same NAME twice would be one row of the CSVs.
  scratch_folder dir;
  const command_result r = run_quadmc(
      dir, {"gallery", "--out", "g", "--points", "mine=a/{N}.csv", "--points", "mine=b/{N}.csv"});
  EXPECT_EQ(r.exit_status, 2) << describe(r);
  EXPECT_NE(r.err.find("--points: expected each NAME once, got 'mine' twice"), std::string::npos)
      << describe(r);
  EXPECT_FALSE(fs::exists(dir / "g"));
}

}  // namespace
}  // namespace quadmc_cli_test
