// Citations in the source tree, checked on the text: comments and theory strings cite
// docs/theory.md#anchor, docs/design.md#anchor and [Key] entries of docs/references.md, never
// files or threads outside the repository.
//
// Why: a citation a reader cannot follow is worse than none. This test fails on a citation of a
// document that is not in the repository (the old THEORY.md, DESIGN.md, "lecture §…", "blog
// seed", "issue N"), on an anchor that no heading of docs/ defines, and on a [Key …] that
// docs/references.md does not list, naming the file and the line. Anchors are GitHub heading
// slugs (lower case, spaces to hyphens, other punctuation dropped); docs/ headings are ASCII so
// that the slug is predictable. Links no layer of the library: it only reads files.
#include "source_tree.hpp"

#include <gtest/gtest.h>

#include <cctype>
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

using quadmc::test_support::source_dir;

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// GitHub's slug of a heading: lower case, spaces to hyphens, everything but letters, digits,
// '-' and '_' dropped.
std::string slug(const std::string& heading) {
  std::string out;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_') {
      out += static_cast<char>(std::tolower(c));
    } else if (c == ' ') {
      out += '-';
    }
  }
  return out;
}

std::set<std::string> anchors_of(const fs::path& markdown) {
  static const std::regex heading(R"(^#+\s+(.*?)\s*$)");
  std::set<std::string> out;
  for (const std::string& line : lines_of(markdown)) {
    std::smatch m;
    if (std::regex_match(line, m, heading)) out.insert(slug(m[1]));
  }
  return out;
}

// The keys of docs/references.md: every "- **[Key]**" entry.
std::set<std::string> reference_keys() {
  static const std::regex entry(R"(^- \*\*\[([^\]]+)\]\*\*)");
  std::set<std::string> out;
  for (const std::string& line : lines_of(source_dir() / "docs/references.md")) {
    std::smatch m;
    if (std::regex_search(line, m, entry)) out.insert(m[1]);
  }
  return out;
}

// Text files of the source tree under `folder` (relative to the source directory).
std::vector<fs::path> text_files(const std::string& folder) {
  static const std::set<std::string> extensions = {".hpp",  ".cpp", ".h",  ".txt",
                                                   ".toml", ".py",  ".md", ".sh"};
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(source_dir() / folder)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (extensions.contains(e.path().extension().string()) || name == "CMakeLists.txt") {
      out.push_back(e.path());
    }
  }
  return out;
}

std::string where(const fs::path& p, std::size_t line) {
  return fs::relative(p, source_dir()).string() + ":" + std::to_string(line + 1);
}

using quadmc::test_support::listed;

// The files that cite: the library, the benchmarks and the tests (this file excepted: it spells
// the forbidden forms out).
std::vector<fs::path> citing_files() {
  std::vector<fs::path> out;
  for (const char* folder : {"lib", "bench", "tests"}) {
    for (const fs::path& p : text_files(folder)) {
      if (p.filename() != "citations_test.cpp") out.push_back(p);
    }
  }
  return out;
}

TEST(Citations, NoSourceOutsideTheRepositoryIsCited) {
  static const std::regex outside(
      R"((THEORY\.md|DESIGN\.md|\b[Ll]ecture\b|blog seed|\bissue [0-9]|the issue's|/work/shared))");
  std::vector<std::string> bad;
  for (const fs::path& p : citing_files()) {
    const std::vector<std::string> lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::smatch m;
      if (std::regex_search(lines[i], m, outside)) {
        bad.push_back(where(p, i) + ": cites \"" + m[1].str() +
                      "\", which is not in the repository; cite docs/theory.md#…, "
                      "docs/design.md#… or a [Key] of docs/references.md");
      }
    }
  }
  EXPECT_TRUE(bad.empty()) << bad.size() << " citation(s) of outside sources:" << listed(bad);
}

TEST(Citations, EveryDocsAnchorExists) {
  const std::map<std::string, std::set<std::string>> anchors = {
      {"theory", anchors_of(source_dir() / "docs/theory.md")},
      {"design", anchors_of(source_dir() / "docs/design.md")},
      {"references", anchors_of(source_dir() / "docs/references.md")},
  };
  ASSERT_TRUE(anchors.at("theory").contains("tensor-rules")) << "docs/theory.md not read";
  static const std::regex cited(R"(docs/(theory|design|references)\.md#([A-Za-z0-9_-]+))");
  // Links inside docs/ itself: (#anchor) and (other.md#anchor).
  static const std::regex linked(R"(\]\(((theory|design|references)\.md)?#([A-Za-z0-9_-]+)\))");
  std::vector<std::string> bad;
  std::size_t citations = 0;
  for (const fs::path& p : citing_files()) {
    const std::vector<std::string> lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), cited);
           it != std::sregex_iterator(); ++it) {
        ++citations;
        if (!anchors.at((*it)[1]).contains((*it)[2])) {
          bad.push_back(where(p, i) + ": no heading of docs/" + (*it)[1].str() + ".md has the " +
                        "anchor #" + (*it)[2].str());
        }
      }
    }
  }
  for (const char* doc : {"theory", "design", "references"}) {
    const fs::path p = source_dir() / "docs" / (std::string(doc) + ".md");
    const std::vector<std::string> lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), linked);
           it != std::sregex_iterator(); ++it) {
        const std::string target = (*it)[2].matched ? (*it)[2].str() : std::string(doc);
        if (!anchors.at(target).contains((*it)[3])) {
          bad.push_back(where(p, i) + ": link to #" + (*it)[3].str() + " of " + target +
                        ".md, which has no such heading");
        }
      }
    }
  }
  EXPECT_GT(citations, 100u) << "the code cites docs/ anchors throughout; found few: regex?";
  EXPECT_TRUE(bad.empty()) << bad.size() << " broken anchor(s):" << listed(bad);
}

// A bracket that reads like a reference key — [Author Year], [A & B], [X et al. …], optionally
// followed by ", §…" — must be an entry of docs/references.md.
TEST(Citations, EveryReferenceKeyIsListed) {
  const std::set<std::string> keys = reference_keys();
  ASSERT_GT(keys.size(), 40u) << "docs/references.md not read";
  static const std::regex bracket(R"(\[([A-Z][^\[\]\n]*?)(, [^\[\]\n]*)?\])");
  static const std::regex key_like(R"((19|20)[0-9]{2}|&| et al\.|ATAP|TAOCP)");
  std::vector<std::string> bad;
  std::vector<fs::path> files = citing_files();
  for (const char* doc : {"theory.md", "design.md"}) files.push_back(source_dir() / "docs" / doc);
  for (const fs::path& p : files) {
    const std::vector<std::string> lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), bracket);
           it != std::sregex_iterator(); ++it) {
        const std::string key = (*it)[1];
        if (std::regex_search(key, key_like) && !keys.contains(key)) {
          bad.push_back(where(p, i) + ": [" + key + "] is not an entry of docs/references.md");
        }
      }
    }
  }
  EXPECT_TRUE(bad.empty()) << bad.size() << " unknown reference key(s):" << listed(bad);
}

TEST(Citations, ReferenceKeysAreUnique) {
  static const std::regex entry(R"(^- \*\*\[([^\]]+)\]\*\*)");
  std::map<std::string, int> seen;
  for (const std::string& line : lines_of(source_dir() / "docs/references.md")) {
    std::smatch m;
    if (std::regex_search(line, m, entry)) ++seen[m[1]];
  }
  for (const auto& [key, count] : seen) EXPECT_EQ(count, 1) << "[" << key << "] listed twice";
}

}  // namespace
