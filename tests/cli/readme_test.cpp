// README.md against the code's own tables: every method, point set, warp and integrand family that
// `quadmc list` prints has a row in the README table of its kind and every row names one of them,
// with the same own keys and controls; and every key the scene parser accepts (parse.hpp's
// scene_keys(), the descriptors' options, the catalogue entries' keys) is documented there.
//
// Use it as the guard that a new method, set, warp, family or scene key reaches the README. The
// tables are found by the first cell of their header row ("method", "point set", "warp",
// "family", "table"), each of which must occur exactly once; a row may name several things when
// they share every checked column. Not a check of the prose: only the tables are read.
#include "quadmc_command.hpp"

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/scene/parse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
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

// The `identifier`s of a cell (backticked words of letters, digits and '_'; other code spans,
// such as `{ name = … }`, are text).
names identifiers(const std::string& cell) {
  names out;
  for (std::size_t open = cell.find('`'); open != std::string::npos;) {
    const std::size_t close = cell.find('`', open + 1);
    if (close == std::string::npos) break;
    const std::string word = cell.substr(open + 1, close - open - 1);
    const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char c) {
      return std::isalnum(c) || c == '_';
    });
    if (plain) out.insert(word);
    open = cell.find('`', close + 1);
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
names point_set_names() {
  names out;
  for (const quadmc::point_set_entry& p : quadmc::point_set_catalogue()) out.emplace(p.name);
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

}  // namespace
}  // namespace quadmc_cli_test
