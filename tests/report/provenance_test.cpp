// Tests for provenance.hpp: meta.csv's columns, its round trip through the CSV quoting, and the
// reader's refusals.
#include "quadmc/report/provenance.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace quadmc {
namespace {

namespace fs = std::filesystem;

struct temporary_file {
  fs::path path;
  explicit temporary_file(const std::string& text) {
    const auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
    path = fs::temp_directory_path() /
           fmt::format("quadmc_meta_{}_{}.csv", tick, std::random_device{}());
    std::ofstream(path, std::ios::binary) << text;
  }
  ~temporary_file() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

provenance sample() {
  provenance p;
  p.version = "0.1.0";
  p.commit = "9e0a32d1b2c3d4e5f60718293a4b5c6d7e8f9012-dirty";
  // A comma and quotes: a compiler string is free text, so the file must quote it.
  p.compiler = "GNU 12.2.0 (\"Release\", -O3)";
  p.simd_levels_available = {"scalar", "sse2", "avx2"};
  p.simd_level = "sse2";
  p.rng = "ars4x32_7";
  return p;
}

TEST(Provenance, MetaCsvIsTheColumnsThenOneRow) {
  EXPECT_EQ(meta_csv_text(sample()),
            "quadmc_version,commit,compiler,simd_levels_available,simd_level,rng\n"
            "0.1.0,9e0a32d1b2c3d4e5f60718293a4b5c6d7e8f9012-dirty,"
            "\"GNU 12.2.0 (\"\"Release\"\", -O3)\",scalar sse2 avx2,sse2,ars4x32_7\n");
}

TEST(Provenance, ReadsBackWhatItWrote) {
  const temporary_file file(meta_csv_text(sample()));
  const provenance p = read_meta_csv(file.path);
  const provenance expected = sample();
  EXPECT_EQ(p.version, expected.version);
  EXPECT_EQ(p.commit, expected.commit);
  EXPECT_EQ(p.compiler, expected.compiler);
  EXPECT_EQ(p.simd_levels_available, expected.simd_levels_available);
  EXPECT_EQ(p.simd_level, expected.simd_level);
  EXPECT_EQ(p.rng, expected.rng);
}

TEST(Provenance, ReaderIgnoresAddedColumns) {
  // Columns may be appended in later versions; a reader of today must still read the file.
  const temporary_file file(
      "quadmc_version,commit,compiler,simd_levels_available,simd_level,later\n"
      "0.2.0,unknown,Clang 14.0.6 (Debug),scalar,scalar,x\n");
  const provenance p = read_meta_csv(file.path);
  EXPECT_EQ(p.version, "0.2.0");
  EXPECT_EQ(p.commit, "unknown");
  EXPECT_EQ(p.simd_levels_available, std::vector<std::string>{"scalar"});
  // Written before the rng column existed, when Philox was the only generator.
  EXPECT_EQ(p.rng, "philox4x32_10");
}

TEST(Provenance, ReaderRefusesAMissingColumnOrAnotherRowCount) {
  const temporary_file no_commit(
      "quadmc_version,compiler,simd_levels_available,simd_level\n0.1.0,GNU,scalar,scalar\n");
  try {
    (void)read_meta_csv(no_commit.path);
    FAIL() << "a missing column must throw";
  } catch (const invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(no_commit.path.string()), std::string::npos) << what;
    EXPECT_NE(what.find("'commit'"), std::string::npos) << what;
  }
  const std::string header = "quadmc_version,commit,compiler,simd_levels_available,simd_level\n";
  const std::string row = "0.1.0,unknown,GNU,scalar,scalar\n";
  for (const std::string& rows : {std::string(), row + row}) {
    const temporary_file file(header + rows);
    try {
      (void)read_meta_csv(file.path);
      FAIL() << "a meta.csv without exactly one row must throw";
    } catch (const invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(file.path.string()), std::string::npos) << what;
      EXPECT_NE(what.find("one row"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace quadmc
