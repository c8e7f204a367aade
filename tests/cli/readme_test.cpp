// README.md against the code's own tables: every method, point set, warp and integrand family that
// `quadmc list` prints has a row in the README table of its kind and every row names one of them,
// with the same own keys and controls; and every key the scene parser accepts (parse.hpp's
// scene_keys(), the descriptors' options, the catalogue entries' keys) is documented there.
//
// Use it as the guard that a new method, set, warp, family or scene key reaches the README. The
// tables are found by the first cell of their header row ("method", "point set", "warp",
// "family", "table"), each of which must occur exactly once; a row may name several things when
// they share every checked column. Not a check of the prose: only the tables are read.
//
// The figures the README quotes from committed results are read back from those results: every
// slope, interval, theory and verdict of "What the default scene shows" (its table headed
// "integrand (s)") from results/default/slopes.csv, each to the decimals it is quoted with.
#include "quadmc_command.hpp"

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/report/results_csv.hpp"
#include "quadmc/scene/parse.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc_cli_test {
namespace {

using names = std::set<std::string, std::less<>>;
using row = std::vector<std::string>;

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// The cells of a Markdown table line; `\|` is a literal bar inside a cell.
row cells_of(const std::string& line) {
  row cells;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (line[i] == '|') {
      cells.push_back(trimmed(cell));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

// The body rows of the one table whose header row starts with the cell `first`.
std::vector<row> readme_table(std::string_view first) {
  std::istringstream in(read_text(fs::path(QUADMC_SOURCE_DIR) / "README.md"));
  std::vector<row> body;
  int found = 0;
  bool inside = false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '|') {
      inside = false;
      continue;
    }
    const row cells = cells_of(line);
    if (!inside && !cells.empty() && cells[0] == first) {
      ++found;
      inside = true;
      std::getline(in, line);  // the |---| separator
      continue;
    }
    if (inside && found == 1) body.push_back(cells);
  }
  EXPECT_EQ(found, 1) << "README.md should have one table headed | " << first << " |";
  return body;
}

// The code spans of a cell (`…`), in order.
std::vector<std::string> code_spans(const std::string& cell) {
  std::vector<std::string> out;
  for (std::size_t open = cell.find('`'); open != std::string::npos;) {
    const std::size_t close = cell.find('`', open + 1);
    if (close == std::string::npos) break;
    out.push_back(cell.substr(open + 1, close - open - 1));
    open = cell.find('`', close + 1);
  }
  return out;
}

// U+2212 minus signs, as the README writes them, as ASCII '-'.
std::string with_ascii_minus(std::string text) {
  for (std::size_t at; (at = text.find("−")) != std::string::npos;) text.replace(at, 3, "-");
  return text;
}

// The `identifier`s of a cell (backticked words of letters, digits and '_'; other code spans,
// such as `{ name = … }`, are text).
names identifiers(const std::string& cell) {
  names out;
  for (const std::string& word : code_spans(cell)) {
    const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char c) {
      return std::isalnum(c) || c == '_';
    });
    if (plain) out.insert(word);
  }
  return out;
}

std::string joined(const names& n) {
  std::string out;
  for (const auto& w : n) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// Each name of `expected` in exactly one row's first cell, and no other name there; returns the
// row of each name.
std::map<std::string, const row*> rows_by_name(const std::vector<row>& table, const names& expected,
                                               std::string_view what) {
  std::map<std::string, const row*> where;
  for (const row& r : table) {
    if (r.empty()) continue;
    for (const std::string& name : identifiers(r[0])) {
      EXPECT_TRUE(expected.contains(name))
          << "README's " << what << " table names `" << name << "`, which the code does not have";
      EXPECT_FALSE(where.contains(name))
          << "README's " << what << " table lists `" << name << "` twice";
      where.emplace(name, &r);
    }
  }
  for (const std::string& name : expected) {
    EXPECT_TRUE(where.contains(name)) << "README's " << what << " table misses `" << name << "`";
  }
  return where;
}

// The names `quadmc list` prints in the section whose heading starts with `heading`: the first
// word of each line indented by exactly two spaces.
names listed(const std::string& listing, std::string_view heading) {
  std::istringstream in(listing);
  names out;
  bool inside = false;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != ' ') inside = line.starts_with(heading);
    if (inside && line.size() > 2 && line.starts_with("  ") && line[2] != ' ') {
      out.insert(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return out;
}

names method_names() {
  names out;
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) out.emplace(m->name);
  return out;
}
// The catalogue's sets and the one that reads the user's files, as `quadmc list` prints them.
names point_set_names() {
  names out;
  for (const quadmc::point_set_entry& p : quadmc::point_set_catalogue()) out.emplace(p.name);
  out.emplace(quadmc::external_point_set);
  return out;
}
names warp_names() {
  names out;
  for (const quadmc::warp_descriptor& w : quadmc::importance_warps()) out.emplace(w.name);
  return out;
}
names family_names() {
  names out;
  for (const quadmc::catalogue_entry& e : quadmc::integrand_catalogue()) out.emplace(e.name);
  return out;
}

TEST(Readme, NamesWhatQuadmcListPrintsAndNothingElse) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"list"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  // The listing and the tables agree, so the README checks below cover what a user sees.
  EXPECT_EQ(listed(r.out, "methods"), method_names());
  EXPECT_EQ(listed(r.out, "point sets"), point_set_names());
  EXPECT_EQ(listed(r.out, "warps"), warp_names());
  EXPECT_EQ(listed(r.out, "integrands"), family_names());
  rows_by_name(readme_table("method"), listed(r.out, "methods"), "method");
  rows_by_name(readme_table("point set"), listed(r.out, "point sets"), "point set");
  rows_by_name(readme_table("warp"), listed(r.out, "warps"), "warp");
  rows_by_name(readme_table("family"), listed(r.out, "integrands"), "family");
}

// | point set | N it holds in s dimensions | …: a set with a largest s states it as `quadmc list`
// does.
TEST(Readme, PointSetTableStatesEachSetsLargestDimension) {
  const std::vector<row> table = readme_table("point set");
  const auto where = rows_by_name(table, point_set_names(), "point set");
  for (const quadmc::point_set_entry& p : quadmc::point_set_catalogue()) {
    const auto it = where.find(std::string(p.name));
    if (p.max_dimension == 0 || it == where.end()) continue;
    ASSERT_GE(it->second->size(), 2u) << p.name;
    EXPECT_NE((*it->second)[1].find("s ≤ " + std::to_string(p.max_dimension)), std::string::npos)
        << p.name << ": " << (*it->second)[1];
  }
}

// | method | kind | control | own keys | what it does |: each method's own keys (its descriptor's
// options) and controls are exactly those of its row.
TEST(Readme, MethodTableHasEachMethodsKindControlsAndKeys) {
  const std::vector<row> table = readme_table("method");
  const auto where = rows_by_name(table, method_names(), "method");
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) {
    const auto it = where.find(std::string(m->name));
    if (it == where.end()) continue;
    const row& r = *it->second;
    ASSERT_GE(r.size(), 4u) << m->name;
    const std::string_view kind =
        m->kind == quadmc::method_kind::deterministic ? "deterministic" : "randomized";
    EXPECT_EQ(r[1], kind) << m->name;
    names controls;
    for (const quadmc::cell_control c : m->controls) controls.emplace(quadmc::to_string(c));
    EXPECT_EQ(joined(identifiers(r[2])), joined(controls)) << m->name << "'s controls";
    names keys;
    for (const quadmc::option_doc& o : m->options) keys.emplace(o.key);
    EXPECT_EQ(joined(identifiers(r[3])), joined(keys)) << m->name << "'s own keys";
  }
}

// | family | keys | …: each family's parameter keys are exactly those of its row.
TEST(Readme, FamilyTableHasEachFamilysKeys) {
  const std::vector<row> table = readme_table("family");
  const auto where = rows_by_name(table, family_names(), "family");
  for (const quadmc::catalogue_entry& e : quadmc::integrand_catalogue()) {
    const auto it = where.find(std::string(e.name));
    if (it == where.end()) continue;
    ASSERT_GE(it->second->size(), 2u) << e.name;
    names keys(e.vector_keys.begin(), e.vector_keys.end());
    keys.insert(e.scalar_keys.begin(), e.scalar_keys.end());
    for (const quadmc::string_key& k : e.string_keys) keys.emplace(k.key);
    EXPECT_EQ(joined(identifiers((*it->second)[1])), joined(keys)) << e.name << "'s keys";
  }
}

// | warp | density | parameter |: the parameter a warp's table form takes.
TEST(Readme, WarpTableHasEachWarpsParameter) {
  const std::vector<row> table = readme_table("warp");
  const auto where = rows_by_name(table, warp_names(), "warp");
  for (const quadmc::warp_descriptor& w : quadmc::importance_warps()) {
    const auto it = where.find(std::string(w.name));
    if (it == where.end()) continue;
    ASSERT_GE(it->second->size(), 3u) << w.name;
    EXPECT_TRUE(identifiers((*it->second)[2]).contains(w.parameter)) << w.name;
  }
}

// | table | key | meaning |: every key of parse.hpp's scene_keys() is in a row of its table (an
// empty first cell continues the table above; a key naming a table, such as `integrand`, is
// documented by that table's rows; the range keys of budget.N in the rows of [budget]), and every
// key a row names is one its table accepts (a [[method]] row may name a method's own key).
TEST(Readme, SceneKeyTableDocumentsEveryKeyTheParserAccepts) {
  const std::map<std::string, std::string, std::less<>> header{{"top", ""},
                                                               {"`[[integrand]]`", "integrand"},
                                                               {"`[[method]]`", "method"},
                                                               {"`[budget]`", "budget"},
                                                               {"`[output]`", "output"}};
  std::map<std::string, names, std::less<>> documented;  // parser table → backticked words
  std::map<std::string, names, std::less<>> key_cells;   // parser table → keys of the key column
  std::string current;
  for (const row& r : readme_table("table")) {
    ASSERT_GE(r.size(), 3u);
    if (!r[0].empty()) {
      const auto it = header.find(r[0]);
      ASSERT_NE(it, header.end()) << "README's key table: unknown table " << r[0];
      current = it->second;
    }
    for (const std::string& cell : r) documented[current].merge(identifiers(cell));
    key_cells[current].merge(identifiers(r[1]));
  }
  names method_keys;
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) {
    for (const quadmc::option_doc& o : m->options) method_keys.emplace(o.key);
  }
  std::map<std::string, names, std::less<>> accepted;
  for (const quadmc::scene_table_keys& t : quadmc::scene_keys()) {
    const std::string table = t.table == "budget.N" ? "budget" : std::string(t.table);
    for (const std::string_view key : t.keys) {
      accepted[table].emplace(key);
      const bool names_a_table = t.table.empty() && documented.contains(key);
      EXPECT_TRUE(names_a_table || documented[table].contains(key))
          << "README's key table misses `" << key << "` of "
          << (t.table.empty() ? std::string("the top level") : std::string(t.table));
    }
  }
  accepted["method"].merge(method_keys);
  for (const auto& [table, keys] : key_cells) {
    for (const std::string& key : keys) {
      EXPECT_TRUE(accepted[table].contains(key))
          << "README's key table documents `" << key << "` in " << (table.empty() ? "top" : table)
          << ", which the parser does not accept there";
    }
  }
}

// The README's section of text between `from` and `to` (both must be there).
std::string readme_between(std::string_view from, std::string_view to) {
  const std::string text = read_text(fs::path(QUADMC_SOURCE_DIR) / "README.md");
  const std::size_t start = text.find(from);
  const std::size_t end = start == std::string::npos ? start : text.find(to, start);
  EXPECT_NE(end, std::string::npos)
      << "README.md should have \"" << from << "\" … \"" << to << "\"";
  return end == std::string::npos ? std::string() : text.substr(start, end - start);
}

// (layer, base name) of every library file: lib/include/quadmc/<layer>/<base>.hpp and
// lib/src/<layer>/<base>.cpp.
std::set<std::pair<std::string, std::string>> library_files() {
  std::set<std::pair<std::string, std::string>> out;
  const fs::path root(QUADMC_SOURCE_DIR);
  for (const auto& [folder, extension] :
       {std::pair{root / "lib/include/quadmc", ".hpp"}, std::pair{root / "lib/src", ".cpp"}}) {
    for (const auto& layer : fs::directory_iterator(folder)) {
      if (!layer.is_directory()) continue;
      for (const auto& file : fs::directory_iterator(layer.path())) {
        if (file.path().extension() == extension) {
          out.emplace(layer.path().filename().string(), file.path().stem().string());
        }
      }
    }
  }
  return out;
}

// "The library" table names every public header (lib/include/quadmc/<layer>/<name>.hpp) in the
// row of its layer.
TEST(Readme, LibraryTableNamesEveryHeader) {
  for (const row& r : readme_table("folder")) {
    ASSERT_GE(r.size(), 2u);
  }
  std::map<std::string, std::string> row_of_layer;
  for (const row& r : readme_table("folder")) row_of_layer[trimmed(r[0])] = r[1];
  const fs::path include(fs::path(QUADMC_SOURCE_DIR) / "lib/include/quadmc");
  for (const auto& layer : fs::directory_iterator(include)) {
    const std::string key = "`" + layer.path().filename().string() + "/`";
    ASSERT_TRUE(row_of_layer.contains(key)) << "README's library table has no row " << key;
    for (const auto& header : fs::directory_iterator(layer.path())) {
      const std::string name = "`" + header.path().filename().string() + "`";
      EXPECT_NE(row_of_layer[key].find(name), std::string::npos)
          << "README's library table does not name " << name << " in its row " << key;
    }
  }
}

// Every library file without tests/<layer>/<file>_test.cpp is named among the exceptions of
// "Tests and CI" (a per-instruction-set kernel by its pattern `*_<isa>.cpp`).
TEST(Readme, EveryUntestedLibraryFileIsAnException) {
  const std::string exceptions = readme_between(
      "A test file is named after the library file it tests", "test a theme across files");
  const fs::path tests(fs::path(QUADMC_SOURCE_DIR) / "tests");
  for (const auto& [layer, base] : library_files()) {
    if (fs::exists(tests / layer / (base + "_test.cpp"))) continue;
    const bool per_isa = base.ends_with("_sse2") || base.ends_with("_avx2") ||
                         base.ends_with("_avx512") || base.ends_with("_avx512_gfni");
    if (per_isa && exceptions.find("`*_<isa>.cpp`") != std::string::npos) continue;
    const bool named = exceptions.find("`" + base + "`") != std::string::npos ||
                       exceptions.find("`" + layer + "/" + base + "`") != std::string::npos ||
                       exceptions.find("`" + base + ".cpp`") != std::string::npos ||
                       exceptions.find("/" + base + ".cpp`") != std::string::npos;
    EXPECT_TRUE(named) << layer << "/" << base << " has no tests/" << layer << "/" << base
                       << "_test.cpp and is not among README's test-file exceptions";
  }
}

// The prose of "What the default scene shows": its cell count and run time are the committed
// page's, and every error it quotes (2 significant digits, as 5.5e-6) is the RMSE or |error| of
// a cell of the committed convergence.csv, so a figure left over from an older run fails here.
TEST(Readme, DefaultSceneProseQuotesTheCommittedPage) {
  const fs::path results = fs::path(QUADMC_SOURCE_DIR) / "results/default";
  const std::string section = with_ascii_minus(
      readme_between("### What the default scene shows", "### The stress and reliability scenes"));
  const auto cells = quadmc::read_convergence_csv(results / "convergence.csv");
  const std::string page = read_text(results / "README.md");
  std::smatch m;
  // The page prints the run time to 3 significant digits: "42 s", "81.8 s".
  ASSERT_TRUE(std::regex_search(section, m, std::regex(R"((\d+) cells in (\d+(?:\.\d+)?) s on)")));
  EXPECT_EQ(m[1].str(), std::to_string(cells.size()))
      << "README's cell count; results/default/convergence.csv has " << cells.size() << " rows";
  EXPECT_NE(page.find("- run time: " + m[2].str() + " s\n"), std::string::npos)
      << "README quotes " << m[2] << " s; results/default/README.md says otherwise";
  std::set<std::string> errors;
  for (const auto& c : cells) {
    for (const double e : {c.rmse, c.mean_abs_error}) {
      if (!std::isfinite(e) || e <= 0.0) continue;
      // "1.9e-04" → "1.9e-4", as the README writes them.
      std::string text = fmt::format("{:.1e}", e);
      const std::size_t exponent = text.find("e-");
      if (exponent != std::string::npos && text[exponent + 2] == '0') text.erase(exponent + 2, 1);
      errors.insert(text);
    }
  }
  const std::regex quoted(R"(\b\d\.\de-\d+\b)");
  std::size_t count = 0;
  for (auto it = std::sregex_iterator(section.begin(), section.end(), quoted);
       it != std::sregex_iterator(); ++it) {
    ++count;
    EXPECT_TRUE(errors.contains(it->str()))
        << "README quotes the error " << it->str()
        << ", which no cell of results/default/convergence.csv has (to 2 digits)";
  }
  EXPECT_GT(count, 0u) << "the section quotes no error: did its wording change?";
}

// "Benchmarks": the QMC point rates quoted against the peers are the committed results/peers/
// page's "quadmc / peer, points per second" rows (s = 2 / s = 8).
TEST(Readme, PeerPointRatesAreTheCommittedPages) {
  const std::string readme = read_text(fs::path(QUADMC_SOURCE_DIR) / "README.md");
  const std::string page = read_text(fs::path(QUADMC_SOURCE_DIR) / "results/peers/README.md");
  struct quote {
    std::string_view after;  // what follows "a× / b×" in the README
    std::string_view quadmc, peer;
  };
  for (const quote& q :
       {quote{"Boost's rate", "quadmc sobol none", "Boost.Random sobol_engine"},
        quote{"GSL's Sobol'", "quadmc sobol none", "GSL sobol"},
        quote{"scipy's", "quadmc sobol none", "scipy Sobol"},
        quote{"GSL's,", "quadmc halton none", "GSL halton"},
        quote{"GSL's reversehalton", "quadmc halton permutation", "GSL reversehalton"}}) {
    std::smatch in_readme, on_page;
    ASSERT_TRUE(std::regex_search(
        readme, in_readme,
        std::regex(R"(([0-9]+\.[0-9]+)× / ([0-9]+\.[0-9]+)× )" + std::string(q.after))))
        << "README should quote a× / b× " << q.after;
    const std::string row = fmt::format("| {} | {} | ", q.quadmc, q.peer);
    const std::size_t at = page.find(row);
    ASSERT_NE(at, std::string::npos) << "results/peers/README.md has no row " << row;
    const std::string line = page.substr(at, page.find('\n', at) - at);
    ASSERT_TRUE(std::regex_search(line, on_page,
                                  std::regex(R"(\| ([0-9]+\.[0-9]+)× \| ([0-9]+\.[0-9]+)× \|$)")))
        << line;
    EXPECT_EQ(in_readme[1].str(), on_page[1].str()) << q.quadmc << " / " << q.peer << ", s = 2";
    EXPECT_EQ(in_readme[2].str(), on_page[2].str()) << q.quadmc << " / " << q.peer << ", s = 8";
  }
  // "In the last committed run (M of T ratios met": the page's own count.
  std::smatch count_in_readme, count_on_page;
  ASSERT_TRUE(
      std::regex_search(readme, count_in_readme,
                        std::regex(R"(last committed run \(([0-9]+) of ([0-9]+) ratios met)")));
  ASSERT_TRUE(std::regex_search(page, count_on_page,
                                std::regex(R"(\*\*([0-9]+) of ([0-9]+) measured ratios met\*\*)")));
  EXPECT_EQ(count_in_readme[1].str() + " of " + count_in_readme[2].str(),
            count_on_page[1].str() + " of " + count_on_page[2].str());
}

// A number as the README quotes it ("−0.724", "-2", "0.5") and how many decimals it has.
struct quoted_number {
  double value;
  int decimals;
  std::string text;
};

// The numbers of a cell outside parentheses, in order; U+2212 minus is a minus.
std::vector<quoted_number> numbers_in(const std::string& quoted) {
  const std::string cell = with_ascii_minus(quoted);
  std::vector<quoted_number> out;
  int depth = 0;
  for (std::size_t i = 0; i < cell.size();) {
    const char c = cell[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    const bool starts =
        std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '-' && i + 1 < cell.size() && std::isdigit(static_cast<unsigned char>(cell[i + 1])));
    if (depth > 0 || !starts) {
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < cell.size() &&
           (std::isdigit(static_cast<unsigned char>(cell[end])) || cell[end] == '.')) {
      ++end;
    }
    const std::string text = cell.substr(i, end - i);
    const std::size_t dot = text.find('.');
    out.push_back({std::stod(text),
                   dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1), text});
    i = end;
  }
  return out;
}

// The verdicts of a cell: its text outside parentheses split at "/"; "agree" is "agrees".
std::vector<std::string> verdicts_in(const std::string& cell) {
  std::string bare;
  int depth = 0;
  for (const char c : cell) {
    if (c == '(') ++depth;
    if (depth == 0) bare += c;
    if (c == ')') --depth;
  }
  std::vector<std::string> out;
  std::istringstream parts(bare);
  for (std::string part; std::getline(parts, part, '/');) {
    part = trimmed(part);
    out.push_back(part == "agree" ? "agrees" : part);
  }
  return out;
}

// `quoted` is `actual` rounded to the quoted decimals.
void expect_quoted(const quoted_number& quoted, double actual, const std::string& what) {
  EXPECT_EQ(fmt::format("{:.{}f}", quoted.value, quoted.decimals),
            fmt::format("{:.{}f}", actual, quoted.decimals))
      << "README quotes " << quoted.text << " for " << what << "; results/default/slopes.csv has "
      << actual;
}

// "What the default scene shows": each row names its series by the integrand and method names
// of the committed page (one integrand with several methods, or several integrands with one), and
// each slope (with its interval where one series is quoted), theory and verdict is the CSV's.
TEST(Readme, DefaultSceneFiguresAreTheCommittedPages) {
  const auto records =
      quadmc::read_slopes_csv(fs::path(QUADMC_SOURCE_DIR) / "results/default/slopes.csv");
  std::map<std::pair<std::string, std::string>, const quadmc::slope_record*> by_series;
  for (const auto& r : records) by_series[{r.integrand, r.method}] = &r;
  const std::vector<row> table = readme_table("integrand (s)");
  ASSERT_FALSE(table.empty());
  for (const row& r : table) {
    ASSERT_EQ(r.size(), 5u) << r[0];
    const auto integrands = code_spans(r[0]);
    const auto methods = code_spans(r[1]);
    ASSERT_TRUE(!integrands.empty() && !methods.empty()) << r[0] << " | " << r[1];
    ASSERT_TRUE(integrands.size() == 1 || methods.size() == 1)
        << "a row quotes one integrand with several methods or several integrands with one: "
        << r[0] << " | " << r[1];
    std::vector<const quadmc::slope_record*> series;
    for (const auto& f : integrands) {
      for (const auto& m : methods) {
        const auto it = by_series.find({f, m});
        ASSERT_NE(it, by_series.end()) << "README quotes " << m << " × " << f
                                       << ", which results/default/slopes.csv does not have";
        series.push_back(it->second);
      }
    }
    const std::string what = r[0] + " | " + r[1];
    const auto slopes = numbers_in(r[2]);
    if (series.size() == 1 && slopes.size() == 3) {  // slope [ci_low, ci_high]
      expect_quoted(slopes[0], series[0]->slope, what + " slope");
      expect_quoted(slopes[1], series[0]->ci_low, what + " ci_low");
      expect_quoted(slopes[2], series[0]->ci_high, what + " ci_high");
    } else {
      ASSERT_EQ(slopes.size(), series.size()) << what << ": one slope per series";
      for (std::size_t i = 0; i < series.size(); ++i) {
        expect_quoted(slopes[i], series[i]->slope, what + " slope " + std::to_string(i + 1));
      }
    }
    const auto theories = numbers_in(r[3]);
    ASSERT_TRUE(theories.size() == 1 || theories.size() == series.size()) << what << ": theory";
    for (std::size_t i = 0; i < series.size(); ++i) {
      expect_quoted(theories[theories.size() == 1 ? 0 : i], series[i]->theory, what + " theory");
    }
    const auto verdicts = verdicts_in(r[4]);
    ASSERT_TRUE(verdicts.size() == 1 || verdicts.size() == series.size()) << what << ": verdict";
    for (std::size_t i = 0; i < series.size(); ++i) {
      EXPECT_EQ(verdicts[verdicts.size() == 1 ? 0 : i], series[i]->verdict)
          << what << ", series " << i + 1;
    }
  }
}

}  // namespace
}  // namespace quadmc_cli_test
