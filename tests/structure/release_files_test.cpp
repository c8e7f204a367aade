// The release files of the source tree agree with the build: LICENSE is the MIT license that
// CITATION.cff declares, CITATION.cff carries CMake's project(VERSION), and CHANGELOG.md has a
// section for that version.
//
// Why: the version is written in three places that nothing else ties together, and a release
// whose citation names the previous version, or whose changelog skips it, is cited and read
// wrongly for as long as it is used. This executable links no layer: it only reads files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string text_of(const std::string& relative) {
  const fs::path p = fs::path(QUADMC_SOURCE_DIR) / relative;
  std::ifstream in(p, std::ios::binary);
  if (!in) ADD_FAILURE() << "cannot read " << p;
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// The VERSION of the top-level project() call.
std::string project_version() {
  static const std::regex project(R"(project\(\s*quadmc\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+))");
  const std::string cmake = text_of("CMakeLists.txt");
  std::smatch m;
  if (!std::regex_search(cmake, m, project)) return {};
  return m[1];
}

TEST(ReleaseFiles, ProjectVersionIsReadable) {
  EXPECT_TRUE(std::regex_match(project_version(), std::regex(R"([0-9]+\.[0-9]+\.[0-9]+)")))
      << "no project(quadmc VERSION x.y.z) in CMakeLists.txt";
}

TEST(ReleaseFiles, CitationCarriesTheProjectVersionAndLicense) {
  const std::string cff = text_of("CITATION.cff");
  static const std::regex version_line(R"re((^|\n)version:[ \t]*"?([^"\n]+?)"?[ \t]*(\n|$))re");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(cff, m, version_line)) << "CITATION.cff has no version: line";
  EXPECT_EQ(m[2].str(), project_version()) << "CITATION.cff's version is not project(VERSION)";
  EXPECT_NE(cff.find("\ncff-version: 1.2.0\n"), std::string::npos);
  EXPECT_NE(cff.find("\nlicense: MIT\n"), std::string::npos);
}

TEST(ReleaseFiles, ChangelogHasASectionForTheProjectVersion) {
  const std::string changelog = text_of("CHANGELOG.md");
  const std::string heading = "\n## [" + project_version() + "]";
  EXPECT_NE(changelog.find(heading), std::string::npos)
      << "CHANGELOG.md has no '## [" << project_version() << "]' section";
}

TEST(ReleaseFiles, LicenseIsMit) {
  const std::string license = text_of("LICENSE");
  EXPECT_EQ(license.rfind("MIT License\n", 0), 0u) << "LICENSE does not start with 'MIT License'";
  EXPECT_NE(license.find("Permission is hereby granted, free of charge"), std::string::npos);
  EXPECT_NE(license.find("THE SOFTWARE IS PROVIDED \"AS IS\""), std::string::npos);
}

}  // namespace
