// Tests for csv.hpp: quoting, parsing, round trip, strict errors.
#include "quadmc/report/csv.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/temporary_directory.hpp"

namespace quadmc {
namespace {

using test_support::temporary_directory;

TEST(Csv, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csv_field("midpoint"), "midpoint");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  const std::vector<std::string> fields = {"x", "1,5", ""};
  EXPECT_EQ(csv_line(fields), "x,\"1,5\",\n");
}

TEST(Csv, RoundTripsAwkwardFields) {
  const std::vector<std::string> header = {"name", "note", "value"};
  const std::vector<std::vector<std::string>> rows = {
      {"genz, \"oscillatory\"", "line one\nline two", "1e-05"},
      {"", ",", "\"\""},
      {"plain", "crlf\r\ninside", "-0"}};
  std::string text = csv_line(header);
  for (const auto& row : rows) text += csv_line(row);
  const csv_table table = parse_csv(text, "memory");
  EXPECT_EQ(table.header, header);
  ASSERT_EQ(table.rows.size(), rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) EXPECT_EQ(table.rows[r], rows[r]) << "row " << r;
}

TEST(Csv, AcceptsCrlfAndNoFinalNewlineSkipsBlankLines) {
  const csv_table table = parse_csv("a,b\r\n1,2\r\n\r\n3,4", "memory");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[1][1], "4");
}

TEST(Csv, ColumnLookupNamesFileAndColumn) {
  const csv_table table = parse_csv("scene,rmse,extra\nx,1,2\n", "results/a/convergence.csv");
  EXPECT_EQ(table.column("rmse"), 1u);
  EXPECT_TRUE(table.has_column("extra"));
  try {
    table.column("slope");
    FAIL() << "missing column must throw";
  } catch (const invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("results/a/convergence.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("'slope'"), std::string::npos) << what;
  }
}

TEST(Csv, MalformedTextThrows) {
  EXPECT_THROW(parse_csv("", "memory"), invalid_argument);
  EXPECT_THROW(parse_csv("a,b\n\"open,2\n", "memory"), invalid_argument);
  EXPECT_THROW(parse_csv("a,b\nx\"y,2\n", "memory"), invalid_argument);
  EXPECT_THROW(parse_csv("a,b\n\"x\"y,2\n", "memory"), invalid_argument);
  EXPECT_THROW(parse_csv("a,b\n1,2,3\n", "memory"), invalid_argument);
  EXPECT_THROW(read_csv_file("/nonexistent/quadmc/none.csv"), invalid_argument);
}

// Regression: a file saved by a spreadsheet as "CSV UTF-8" starts with a byte-order mark, which
// became part of the first column's name ("missing column 'scene'").
TEST(Csv, AByteOrderMarkBeforeTheHeaderIsNotPartOfTheFirstColumn) {
  const temporary_directory dir{"quadmc_csv_bom", temporary_directory::start::empty};
  const std::filesystem::path file = dir.path / "slopes.csv";
  std::ofstream(file, std::ios::binary) << "\xEF\xBB\xBFscene,s\ndefault,2\n";
  const csv_table table = read_csv_file(file);
  EXPECT_EQ(table.rows.at(0).at(table.column("scene")), "default");
}

}  // namespace
}  // namespace quadmc
