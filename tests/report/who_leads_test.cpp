// Tests for who_leads.hpp: the "Who leads at equal N" computation and who_leads.csv. The tables'
// layout on the page is tested in markdown_report_test.cpp (WhoLeadsAtEqualNPerFamilyAndDimension).
#include "quadmc/report/who_leads.hpp"

#include "../analysis/series_builder.hpp"
#include "quadmc/report/csv.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::repetition;
using test::rule_theory;
using test::series_of;
using test_support::nan;

// rule_a 8/N, rule_b 1/N on fam_s2 over N = 16, 64, 256, 1024, 4096; rule_b skips N = 256, where
// it competes with its cell of N = 64.
std::vector<convergence_table> two_rules() {
  std::vector<convergence_table> tables;
  for (const auto& [method, c] : {std::pair{"rule_a", 8.0}, std::pair{"rule_b", 1.0}}) {
    convergence_series series =
        series_of("fam_s2", 2, method, smoothness::c0, 1.0, rule_theory(2, smoothness::c0, 2));
    for (std::uint64_t n = 16; n <= 4096; n *= 4) {
      if (c == 1.0 && n == 256) continue;
      const double x = static_cast<double>(n);
      series.cells.push_back(cell_at(n, {repetition(1.0 + c / x, nan, n, 1e-6)}));
    }
    tables.push_back(analyse_convergence(series));
  }
  return tables;
}

TEST(WhoLeads, OneRowPerDimensionOneCellPerLadderN) {
  const auto tables = two_rules();
  const auto families = who_leads(tables);
  ASSERT_EQ(families.size(), 1u);
  const family_leaders& f = families[0];
  EXPECT_EQ(f.family, "fam");
  EXPECT_EQ(f.regularity, smoothness::c0);
  EXPECT_EQ(f.ladder, (std::vector<std::uint64_t>{16, 64, 256, 1024, 4096}));
  ASSERT_EQ(f.rows.size(), 1u);
  ASSERT_EQ(f.rows[0].cells.size(), 5u);
  for (const auto& c : f.rows[0].cells) {
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->method, "rule_b");
    EXPECT_FALSE(c->at_floor);
  }
  // N = 256: rule_b competes with its 1/64 of N = 64 and beats rule_a's 8/256 = 1/32.
  EXPECT_EQ(f.rows[0].cells[2]->at_n, 64u);
  EXPECT_EQ(f.rows[0].cells[0]->at_n, 16u);
}

// who_leads.csv has the tables' shape: a row per (family, s, N), "—" cells with empty fields.
TEST(WhoLeads, CsvHoldsEveryCellOfTheTables) {
  const auto tables = two_rules();
  const csv_table csv = parse_csv(who_leads_csv_text("unit", who_leads(tables)), "who_leads.csv");
  EXPECT_EQ(csv.header, (std::vector<std::string>{"scene", "family", "s", "N", "method", "error",
                                                  "at_N", "at_floor"}));
  ASSERT_EQ(csv.rows.size(), 5u);  // N = 16, 64, 256, 1024, 4096
  // Errors in the shortest text that reads back to the same double; at_N the cell competed with.
  EXPECT_EQ(csv.rows[0],
            (std::vector<std::string>{"unit", "fam", "2", "16", "rule_b", "0.0625", "16", "0"}));
  EXPECT_EQ(csv.rows[2],
            (std::vector<std::string>{"unit", "fam", "2", "256", "rule_b", "0.015625", "64", "0"}));
}

// A family with one method has no table, and a "—" cell (an N of the family's ladder where one
// method competes in this s) is a row with empty method, error and at_N.
TEST(WhoLeads, DashCellsAreRowsWithEmptyFields) {
  auto tables = two_rules();
  // fam in s = 4 too: rule_a from N = 16, rule_b from N = 64, so (s = 4, N = 16) is "—".
  for (const auto& [method, from] : {std::pair{"rule_a", 16u}, std::pair{"rule_b", 64u}}) {
    convergence_series series =
        series_of("fam_s4", 4, method, smoothness::c0, 1.0, rule_theory(2, smoothness::c0, 4));
    for (std::uint64_t n = from; n <= 4096; n *= 4) {
      const double x = static_cast<double>(n);
      series.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / x, nan, n, 1e-6)}));
    }
    tables.push_back(analyse_convergence(series));
  }
  convergence_series solo =
      series_of("solo", 1, "rule_a", smoothness::c0, 1.0, rule_theory(2, smoothness::c0));
  for (const std::uint64_t n : {16u, 64u, 256u}) {
    const double x = static_cast<double>(n);
    solo.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / x, nan, n, 1e-6)}));
  }
  tables.push_back(analyse_convergence(solo));
  const auto families = who_leads(tables);
  ASSERT_EQ(families.size(), 1u) << "solo has one method: no table";
  ASSERT_EQ(families[0].rows.size(), 2u);
  EXPECT_EQ(families[0].rows[1].s, 4u);
  EXPECT_FALSE(families[0].rows[1].cells[0].has_value());
  const csv_table csv = parse_csv(who_leads_csv_text("unit", families), "who_leads.csv");
  ASSERT_EQ(csv.rows.size(), 10u);  // two rows of five N
  EXPECT_EQ(csv.rows[5], (std::vector<std::string>{"unit", "fam", "4", "16", "", "", "", ""}));
}

}  // namespace
}  // namespace quadmc
