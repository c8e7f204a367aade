// Tests for answer_first.hpp: the lines at the top of a results page follow the "Who leads" tables
// (who_leads.hpp) and the slope verdicts, stay within five lines, and link only what exists.
#include "quadmc/report/answer_first.hpp"

#include "../analysis/series_builder.hpp"
#include "quadmc/report/who_leads.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::repetition;
using test::rule_theory;
using test::series_of;
using test_support::nan;

// Two rules on one family over N = 16, 64, …, 4096: rule_a's error is a·N^(−2/s), rule_b's
// b·N^(−2/s) (a tensor rule of order 2, on its theory), so the smaller constant leads at every N.
std::vector<convergence_table> two_rules(double a, double b, smoothness regularity,
                                         const std::string& family = "fam", std::size_t s = 2) {
  const std::string integrand = fmt::format("{}_s{}", family, s);
  std::vector<convergence_table> tables;
  for (const auto& [method, c] : {std::pair{"rule_a", a}, std::pair{"rule_b", b}}) {
    convergence_series series =
        series_of(integrand, s, method, regularity, 1.0, rule_theory(2, regularity, s));
    for (std::uint64_t n = 16; n <= 4096; n *= 4) {
      const double x = static_cast<double>(n);
      const double error = c * std::pow(x, -2.0 / static_cast<double>(s));
      series.cells.push_back(cell_at(n, {repetition(1.0 + error, nan, n, 1e-6)}));
    }
    tables.push_back(analyse_convergence(series));
  }
  return tables;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

// The sentence is made from the table: swap which rule has the smaller error and the leader the
// first line names changes with it.
TEST(AnswerFirst, TheLeaderNamedIsTheTablesWinner) {
  const auto b_leads = two_rules(4.0, 1.0, smoothness::analytic);
  const auto families_b = who_leads(b_leads);
  ASSERT_EQ(families_b.size(), 1u);
  ASSERT_TRUE(families_b[0].rows[0].cells[0].has_value());
  EXPECT_EQ(families_b[0].rows[0].cells[0]->method, "rule_b");
  const std::string first_b = answer_first_lines(b_leads, families_b, false).front();
  EXPECT_NE(first_b.find("`rule_b` leads `fam` (s = 2) at every N"), std::string::npos) << first_b;
  EXPECT_EQ(first_b.find("rule_a"), std::string::npos) << first_b;

  const auto a_leads = two_rules(1.0, 4.0, smoothness::analytic);
  const std::string first_a = answer_first_lines(a_leads, who_leads(a_leads), false).front();
  EXPECT_NE(first_a.find("`rule_a` leads `fam` (s = 2) at every N"), std::string::npos) << first_a;
  EXPECT_NE(first_a, first_b);
}

// A winner that changes along the ladder: the line names the last one and the N it leads from;
// one that changes at the last N only is no steady leader.
TEST(AnswerFirst, TheLeaderFromTheNWhereItTakesOver) {
  std::vector<convergence_table> tables;
  convergence_series a = series_of("fam_s2", 2, "rule_a", smoothness::analytic, 1.0,
                                   rule_theory(2, smoothness::analytic, 2));
  convergence_series b = series_of("fam_s2", 2, "rule_b", smoothness::analytic, 1.0,
                                   rule_theory(4, smoothness::analytic, 2));
  for (std::uint64_t n = 16; n <= 4096; n *= 4) {
    const double x = static_cast<double>(n);
    // a: 1/N; b: 64/N² — b leads from N = 256 (64/256² = 1/1024 < 1/256; at N = 64, 1/64 = a's).
    a.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / x, nan, n, 1e-6)}));
    b.cells.push_back(cell_at(n, {repetition(1.0 + 64.0 / (x * x), nan, n, 1e-6)}));
  }
  tables = {analyse_convergence(a), analyse_convergence(b)};
  std::string first = answer_first_lines(tables, who_leads(tables), false).front();
  EXPECT_NE(first.find("`rule_b` leads `fam` (s = 2) from N = 256."), std::string::npos) << first;

  // rule_a wins the last N only (a at 4096: 1e-9): no steady leader.
  a.cells.back().repetitions = {repetition(1.0 + 1e-9, nan, 4096, 1e-6)};
  tables = {analyse_convergence(a), analyse_convergence(b)};
  first = answer_first_lines(tables, who_leads(tables), false).front();
  EXPECT_NE(first.find("no steady leader on `fam` (s = 2)."), std::string::npos) << first;
}

// However many families, classes and dimensions: five lines at most, one per kind.
TEST(AnswerFirst, AtMostFiveLinesHoweverLargeTheScene) {
  std::vector<convergence_table> tables;
  const smoothness classes[] = {smoothness::analytic, smoothness::smooth, smoothness::c0,
                                smoothness::discontinuous, smoothness::singular};
  for (int k = 0; k < 40; ++k) {
    for (const std::size_t s : {2u, 4u, 8u}) {
      const auto two = two_rules(1.0 + k, 2.0, classes[k % 5], fmt::format("f{}", k), s);
      tables.insert(tables.end(), two.begin(), two.end());
    }
  }
  const auto families = who_leads(tables);
  EXPECT_EQ(families.size(), 40u);
  const auto lines = answer_first_lines(tables, families, true);
  EXPECT_EQ(lines.size(), 5u) << joined(lines);
  for (const std::string& line : lines) {
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  }
  EXPECT_NE(lines[0].find("**Smooth integrands"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("**Their largest s:**"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find("not smooth"), std::string::npos) << lines[2];
  EXPECT_EQ(lines[3].rfind("**Slopes:** ", 0), 0u) << lines[3];
  EXPECT_NE(lines[4].find("](who_leads.svg)"), std::string::npos) << lines[4];
}

// Verdict counts and findings: a series that disagrees without a computed reason is named and the
// Findings section linked; without figures there is no link to a file.
TEST(AnswerFirst, SlopeCountsNameTheFindings) {
  auto tables = two_rules(1.0, 2.0, smoothness::analytic);
  // rule_c: error N^(−1/2) where the theory says N⁻¹ (order 2 in s = 2): shallower, a finding.
  convergence_series c = series_of("fam_s2", 2, "rule_c", smoothness::analytic, 1.0,
                                   rule_theory(2, smoothness::analytic, 2));
  for (std::uint64_t n = 16; n <= 4096; n *= 4) {
    const double error = 1.0 / std::sqrt(static_cast<double>(n));
    c.cells.push_back(cell_at(n, {repetition(1.0 + error, nan, n, 1e-6)}));
  }
  tables.push_back(analyse_convergence(c));
  ASSERT_EQ(tables.back().verdict, slope_verdict::shallower);
  const auto lines = answer_first_lines(tables, who_leads(tables), false);
  const std::string& slopes = lines.back();
  EXPECT_NE(slopes.find("**Slopes:** 2 of 3 series agree with theory"), std::string::npos)
      << slopes;
  EXPECT_NE(slopes.find("1 disagrees with no computed reason ([Findings](#findings)): "
                        "`fam_s2` (s = 2) `rule_c` shallower."),
            std::string::npos)
      << slopes;
  for (const std::string& line : lines) {
    EXPECT_EQ(line.find(".svg"), std::string::npos) << line;
    EXPECT_EQ(line.find(".png"), std::string::npos) << line;
  }
}

// A page with one method per family has no "Who leads" table: the first line says so and what
// the page has instead, and the figure of a table that does not exist is not linked.
TEST(AnswerFirst, WithoutATableTheLinesSayWhatThePageHas) {
  convergence_series a = series_of("solo", 1, "rule_a", smoothness::analytic, 1.0,
                                   rule_theory(2, smoothness::analytic));
  for (std::uint64_t n = 16; n <= 4096; n *= 4) {
    const double x = static_cast<double>(n);
    a.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / (x * x), nan, n, 1e-6)}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(a)};
  const auto families = who_leads(tables);
  EXPECT_TRUE(families.empty());
  const auto lines = answer_first_lines(tables, families, true);
  ASSERT_EQ(lines.size(), 3u) << joined(lines);
  EXPECT_NE(lines[0].find("no \"Who leads at equal N\" table"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("1 series of 1 (integrand, s) group"), std::string::npos) << lines[0];
  EXPECT_NE(lines[2].find("](slope_against_theory.svg)"), std::string::npos) << lines[2];
  EXPECT_EQ(lines[2].find("who_leads"), std::string::npos) << lines[2];
}

}  // namespace
}  // namespace quadmc
