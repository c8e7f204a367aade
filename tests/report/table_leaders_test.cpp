// Tests for table_leaders.hpp: the answer lines of the gallery and render pages are read from their
// tables, so changing one row of a synthetic table changes the sentence, with the rule of the run
// pages' "Who leads" (a steady leader from the column where its run of wins starts).
#include "quadmc/report/table_leaders.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace quadmc {
namespace {

// D* of three point sets at N = 16, 64, 256, as the gallery's table gives them.
scored_table discrepancies() {
  return {"N",
          {16, 64, 256},
          {"independent", "jittered", "sobol"},
          {{0.088, 0.044, 0.022}, {0.050, 0.018, 0.0065}, {0.060, 0.015, 0.0040}}};
}

TEST(TableLeaders, TheLeaderIsTheLastColumnsWinnerFromWhereItsRunStarts) {
  const scored_table t = discrepancies();
  const auto winners = column_winners(t);
  ASSERT_EQ(winners.size(), 3u);
  EXPECT_EQ(winners[0], std::optional<std::size_t>{1});
  EXPECT_EQ(winners[1], std::optional<std::size_t>{2});
  EXPECT_EQ(winners[2], std::optional<std::size_t>{2});
  EXPECT_EQ(leaders_phrase(t, "independent"),
            "`sobol` leads from N = 64 (0.004 at N = 256, 5.5× below `independent`'s 0.022)");
}

// A changed row changes the sentence: jittered's figures made the smallest everywhere.
TEST(TableLeaders, ChangingARowChangesTheSentence) {
  scored_table t = discrepancies();
  const std::string before = leaders_phrase(t);
  t.values[1] = {0.010, 0.005, 0.0025};
  const std::string after = leaders_phrase(t);
  EXPECT_NE(before, after);
  EXPECT_EQ(after, "`jittered` leads at every N (0.0025 at N = 256)");
  // And a winner of the last column alone is no steady leader: both winners are named.
  t.values[2][2] = 0.001;
  EXPECT_EQ(leaders_phrase(t), "no steady leader (`jittered` at N = 64, `sobol` at N = 256)");
}

TEST(TableLeaders, TiesGoToTheRowListedFirstAndMissingValuesDoNotCompete) {
  scored_table t{"spp", {1, 4}, {"a", "b"}, {{std::nullopt, 0.5}, {0.7, 0.5}}};
  const auto winners = column_winners(t);
  EXPECT_EQ(winners[0], std::optional<std::size_t>{1});
  EXPECT_EQ(winners[1], std::optional<std::size_t>{0});
  // The baseline equal to the leader's figure is no comparison ("1× below" says nothing).
  EXPECT_EQ(leaders_phrase(t, "b"), "no steady leader (`b` at spp = 1, `a` at spp = 4)");
  t.values = {{std::nullopt, std::nullopt}, {std::nullopt, std::nullopt}};
  EXPECT_EQ(leaders_phrase(t), "no figures");
  t.columns = {4};
  t.values = {{0.5}, {0.5}};
  EXPECT_EQ(leaders_phrase(t, "b"), "`a` leads at spp = 4 (0.5 at spp = 4)");
}

TEST(TableLeaders, AMisshapenTableIsRefusedNamingTheRow) {
  scored_table t = discrepancies();
  t.values[2].pop_back();
  try {
    (void)column_winners(t);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("scored_table.values[2]"), std::string::npos) << e.what();
  }
  t.values.pop_back();
  EXPECT_THROW((void)leaders_phrase(t), invalid_argument);
}

}  // namespace
}  // namespace quadmc
