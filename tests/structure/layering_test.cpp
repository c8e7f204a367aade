// The layering of lib/, checked on the source text: every `#include "quadmc/<layer>/…"` of
// lib/include/quadmc/<layer>/ and lib/src/<layer>/ must name the file's own layer or one the
// table below allows (docs/design.md#layers).
//
// Why a test and not the link graph: every layer target exports the same include root
// (lib/CMakeLists.txt), so a header-only upward include — rules/ including scene/ — compiles and
// links; only reading the includes finds it. The table is the transitive closure of the direct
// dependencies written here, which must match the DEPS of lib/CMakeLists.txt (checked below).
// This executable links no layer of the library: it only reads files under QUADMC_SOURCE_DIR.
#include "source_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using layer_graph = std::map<std::string, std::set<std::string>>;

// Direct dependencies, lowest layers first: core < functions < rules, sampling < estimators;
// core < analysis; methods on rules, estimators and analysis; scene on methods (and so on
// everything below it); report on analysis and scene (it writes what a scene's run computed).
// `methods` may not exist yet; an entry for a missing folder is harmless.
const layer_graph direct_dependencies = {
    {"core", {}},
    {"functions", {"core"}},
    {"rules", {"functions"}},
    {"sampling", {"functions"}},
    {"estimators", {"sampling"}},
    {"analysis", {"core"}},
    {"methods", {"rules", "estimators", "analysis"}},
    {"scene", {"methods", "rules", "estimators", "analysis"}},
    {"report", {"analysis", "scene"}},
};

layer_graph transitive_closure(const layer_graph& direct) {
  layer_graph closed = direct;
  for (bool grew = true; grew;) {
    grew = false;
    for (auto& [layer, deps] : closed) {
      std::set<std::string> more = deps;
      for (const std::string& d : deps) {
        const auto it = closed.find(d);
        if (it != closed.end()) more.insert(it->second.begin(), it->second.end());
      }
      if (more.size() != deps.size()) {
        deps = std::move(more);
        grew = true;
      }
    }
  }
  return closed;
}

std::string joined(const std::set<std::string>& names) {
  if (names.empty()) return "nothing";
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

using quadmc::test_support::source_dir;

struct include_edge {
  std::string file;  // relative to the source directory
  int line = 0;
  std::string from_layer;
  std::string to_layer;
  std::string target;  // the quoted path
};

// Every `#include "quadmc/<layer>/…"` (or <…>) of the files under root/<layer>/, and every
// relative include that climbs out of its folder (`"../…"`, reported with to_layer "..").
std::vector<include_edge> includes_under(const fs::path& root) {
  static const std::regex include_line(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  static const std::regex quadmc_path(R"(^quadmc/([A-Za-z0-9_]+)/)");
  std::vector<include_edge> edges;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp" && ext != ".h") continue;
    const fs::path relative = fs::relative(entry.path(), root);
    const std::string from = relative.begin()->string();
    std::ifstream in(entry.path());
    std::string text;
    int number = 0;
    while (std::getline(in, text)) {
      ++number;
      std::smatch m;
      if (!std::regex_search(text, m, include_line)) continue;
      const std::string target = m[1];
      const std::string where = fs::relative(entry.path(), source_dir()).string();
      std::smatch q;
      if (std::regex_search(target, q, quadmc_path)) {
        edges.push_back({where, number, from, q[1], target});
      } else if (target.starts_with("../") || target.find("/../") != std::string::npos) {
        edges.push_back({where, number, from, "..", target});
      }
    }
  }
  return edges;
}

// The folders (layers) directly under root.
std::set<std::string> layers_under(const fs::path& root) {
  std::set<std::string> out;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.is_directory()) out.insert(entry.path().filename().string());
  }
  return out;
}

// Violations of `allowed` among `edges`, one line each: file:line: the edge and what is allowed.
std::vector<std::string> violations(const std::vector<include_edge>& edges,
                                    const layer_graph& allowed) {
  std::vector<std::string> out;
  for (const include_edge& e : edges) {
    const auto it = allowed.find(e.from_layer);
    if (it == allowed.end()) {
      out.push_back(e.file + ":" + std::to_string(e.line) + ": layer '" + e.from_layer +
                    "' is not in the layer table of tests/structure/layering_test.cpp");
      continue;
    }
    if (e.to_layer == "..") {
      out.push_back(e.file + ":" + std::to_string(e.line) + ": relative include \"" + e.target +
                    "\" leaves its folder; include \"quadmc/<layer>/…\" instead");
      continue;
    }
    if (e.to_layer == e.from_layer || it->second.contains(e.to_layer)) continue;
    out.push_back(e.file + ":" + std::to_string(e.line) + ": " + e.from_layer + " -> " +
                  e.to_layer + " (\"" + e.target + "\"): " + e.from_layer + " may include only " +
                  joined(it->second) + " and itself");
  }
  return out;
}

using quadmc::test_support::listed;

TEST(Layering, EveryLibraryFolderIsALayerOfTheTable) {
  const layer_graph allowed = transitive_closure(direct_dependencies);
  for (const fs::path& root : {source_dir() / "lib/include/quadmc", source_dir() / "lib/src"}) {
    ASSERT_TRUE(fs::is_directory(root)) << root;
    for (const std::string& layer : layers_under(root)) {
      EXPECT_TRUE(allowed.contains(layer))
          << root.string() << "/" << layer << " is not in the layer table; add it with its "
          << "dependencies (and to docs/design.md#layers)";
    }
  }
}

TEST(Layering, HeadersIncludeOnlyTheirOwnLayerAndBelow) {
  const std::vector<include_edge> edges = includes_under(source_dir() / "lib/include/quadmc");
  ASSERT_FALSE(edges.empty()) << "no quadmc includes found: wrong QUADMC_SOURCE_DIR?";
  const std::vector<std::string> bad = violations(edges, transitive_closure(direct_dependencies));
  EXPECT_TRUE(bad.empty()) << bad.size() << " include(s) against the layering:" << listed(bad);
}

TEST(Layering, SourcesIncludeOnlyTheirOwnLayerAndBelow) {
  const std::vector<include_edge> edges = includes_under(source_dir() / "lib/src");
  ASSERT_FALSE(edges.empty()) << "no quadmc includes found: wrong QUADMC_SOURCE_DIR?";
  const std::vector<std::string> bad = violations(edges, transitive_closure(direct_dependencies));
  EXPECT_TRUE(bad.empty()) << bad.size() << " include(s) against the layering:" << listed(bad);
}

// The rule itself, on made-up edges: an upward, a sideways and a climbing include are caught,
// a downward and a transitive one pass.
TEST(Layering, TheCheckCatchesUpwardSidewaysAndRelativeIncludes) {
  const layer_graph allowed = transitive_closure(direct_dependencies);
  const std::vector<include_edge> edges = {
      {"lib/include/quadmc/rules/midpoint_rule.hpp", 3, "rules", "scene", "quadmc/scene/plan.hpp"},
      {"lib/include/quadmc/rules/x.hpp", 4, "rules", "sampling", "quadmc/sampling/warp.hpp"},
      {"lib/src/report/x.cpp", 5, "report", "..", "../scene/run.hpp"},
      {"lib/include/quadmc/estimators/x.hpp", 6, "estimators", "core", "quadmc/core/rng.hpp"},
      {"lib/src/scene/x.cpp", 7, "scene", "functions", "quadmc/functions/genz.hpp"},
  };
  const std::vector<std::string> bad = violations(edges, allowed);
  ASSERT_EQ(bad.size(), 3u) << listed(bad);
  EXPECT_EQ(bad[0],
            "lib/include/quadmc/rules/midpoint_rule.hpp:3: rules -> scene "
            "(\"quadmc/scene/plan.hpp\"): rules may include only core, functions and itself");
  EXPECT_NE(bad[1].find("rules -> sampling"), std::string::npos) << bad[1];
  EXPECT_NE(bad[2].find("leaves its folder"), std::string::npos) << bad[2];
}

// The table must say what lib/CMakeLists.txt links: for every layer CMake defines, the closure of
// its quadmc_* DEPS equals the table's closure restricted to the layers CMake defines. A DEPS
// edge the table lacks (or the reverse) fails here, so neither can drift from the other.
TEST(Layering, TableMatchesTheDepsOfLibCMakeLists) {
  std::ifstream in(source_dir() / "lib/CMakeLists.txt");
  ASSERT_TRUE(in) << "cannot read lib/CMakeLists.txt";
  std::stringstream text;
  text << in.rdbuf();
  const std::string cmake = text.str();
  static const std::regex layer_call(R"(quadmc_layer\(\s*([A-Za-z0-9_]+)\s+DEPS([^)]*)\))");
  static const std::regex layer_target(R"(quadmc_([A-Za-z0-9_]+))");
  layer_graph linked;
  for (auto it = std::sregex_iterator(cmake.begin(), cmake.end(), layer_call);
       it != std::sregex_iterator(); ++it) {
    std::set<std::string>& deps = linked[(*it)[1]];
    const std::string args = (*it)[2];
    for (auto d = std::sregex_iterator(args.begin(), args.end(), layer_target);
         d != std::sregex_iterator(); ++d) {
      const std::string dep = (*d)[1];
      if (dep != "random123") deps.insert(dep);  // the Random123 include path, not a layer
    }
  }
  ASSERT_TRUE(linked.contains("core") && linked.contains("scene"))
      << "no quadmc_layer(… DEPS …) calls found in lib/CMakeLists.txt";
  const layer_graph from_cmake = transitive_closure(linked);
  const layer_graph from_table = transitive_closure(direct_dependencies);
  for (const auto& [layer, deps] : from_cmake) {
    ASSERT_TRUE(from_table.contains(layer)) << "CMake layer " << layer << " is not in the table";
    std::set<std::string> expected;
    for (const std::string& d : from_table.at(layer)) {
      if (from_cmake.contains(d)) expected.insert(d);
    }
    EXPECT_EQ(joined(deps), joined(expected))
        << "layer " << layer << ": lib/CMakeLists.txt links (transitively) " << joined(deps)
        << ", the table allows " << joined(expected);
  }
}

}  // namespace
