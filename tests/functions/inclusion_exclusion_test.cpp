// Alternating vertex sums: small cases by hand, and the Gray-code order visiting every vertex.
#include "quadmc/functions/inclusion_exclusion.hpp"

#include <gtest/gtest.h>

namespace quadmc {
namespace {

TEST(AlternatingVertexSum, SmallCasesByHand) {
  const std::vector<double> a = {0.5, 2.0};
  // g(t) = t²: 0 − 0.25 − 4 + 6.25 = 2 = 2·a₁a₂ (the mixed second difference of t²).
  const vertex_sum sum = alternating_vertex_sum(a, [](const wide_float& t, const wide_float& dt) {
    return std::pair{wide_float(t * t), wide_float(2 * dt)};
  });
  EXPECT_EQ(static_cast<double>(sum.value), 2.0);
  EXPECT_LT(static_cast<double>(sum.error_bound), 1e-45);
  // g ≡ 1 on s ≥ 1: the signs cancel exactly; the vertex count is 2^s.
  int visits = 0;
  const std::vector<double> b(10, 0.1);
  const vertex_sum ones = alternating_vertex_sum(b, [&](const wide_float&, const wide_float&) {
    ++visits;
    return std::pair{wide_float(1), wide_float(0)};
  });
  EXPECT_EQ(visits, 1024);
  EXPECT_EQ(static_cast<double>(ones.value), 0.0);
}

TEST(AlternatingVertexSum, GrayCodeReachesEveryVertexSum) {
  // With a = (1, 2, 4, 8) every vertex has a distinct a·v in 0..15: all must be visited once.
  const std::vector<double> a = {1, 2, 4, 8};
  std::vector<int> seen(16, 0);
  alternating_vertex_sum(a, [&](const wide_float& t, const wide_float&) {
    ++seen.at(static_cast<std::size_t>(static_cast<double>(t)));
    return std::pair{wide_float(0), wide_float(0)};
  });
  for (int k = 0; k < 16; ++k) EXPECT_EQ(seen[k], 1) << "a·v = " << k;
}

}  // namespace
}  // namespace quadmc
