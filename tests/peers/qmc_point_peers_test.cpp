// Tests of bench/peers/qmc_point_peers.cpp: the two kinds its claims check (nets, stratified
// Halton coordinates) accept the sets that have them and reject independent points, and every
// claim of check_point_agreement holds on the generators the peers study times — Boost.Random and
// GSL always, scipy where Debian's python3-scipy is installed (else the scipy test skips, saying
// so).
#include "qmc_point_peers.hpp"

#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

namespace quadmc::peers {
namespace {

template <class P>
std::vector<double> points(std::size_t s, std::uint64_t n) {
  const P set(s, n, 3, 4);
  std::vector<double> x(s * n);
  set.generate(0, std::span<double>(x));
  return x;
}

TEST(QmcPointKinds, NetCheckAcceptsSobolPointsAndRejectsIndependentOnes) {
  constexpr unsigned m = 10;
  EXPECT_TRUE(is_zero_m_2_net(points<sobol_points<unrandomized_digits>>(2, 1 << m), m));
  EXPECT_TRUE(is_zero_m_2_net(points<sobol_points<owen_scramble>>(2, 1 << m), m));
  // Independent uniforms: a (0, 10, 2)-net needs, among others, one point in each of the 1024
  // boxes of width 2^−10: probability 1024!/1024^1024 ≈ e^−1020, never.
  EXPECT_FALSE(is_zero_m_2_net(points<independent_points>(2, 1 << m), m));
}

TEST(QmcPointKinds, StratificationCheckAcceptsHaltonPointsAndRejectsIndependentOnes) {
  constexpr std::uint64_t n = 1000;
  EXPECT_TRUE(
      stratifies_each_coordinate(points<halton_points<unrandomized_radical_inverse>>(4, n), n, 4));
  EXPECT_TRUE(
      stratifies_each_coordinate(points<halton_points<random_digit_permutation>>(4, n), n, 4));
  // Independent uniforms: 512 points in 512 cells all distinct has probability 512!/512^512 ≈
  // e^−510.
  EXPECT_FALSE(stratifies_each_coordinate(points<independent_points>(4, n), n, 4));
}

std::vector<point_generator> generators(bool with_scipy) {
  std::vector<point_generator> g =
      qmc_point_generators(QUADMC_PEERS_PYTHON, QUADMC_PEERS_SCIPY_SCRIPT);
  if (!with_scipy) {
    g.erase(std::remove_if(g.begin(), g.end(),
                           [](const point_generator& p) { return p.family == "scipy"; }),
            g.end());
  }
  return g;
}

TEST(QmcPointPeers, BoostAndGslMakePointsOfTheKindTheyAreComparedWith) {
  int checked = 0;
  for (const point_agreement& a : check_point_agreement(generators(false))) {
    if (a.peer.rfind("scipy", 0) == 0) continue;  // not in this list: the next test
    ++checked;
    EXPECT_TRUE(a.holds) << a.peer << ": " << a.claim << " (" << a.detail << ")";
  }
  EXPECT_EQ(checked, 5);  // Boost sobol_engine, GSL sobol, niederreiter_2, halton, reversehalton
}

TEST(QmcPointPeers, ScipyMakesPointsOfTheKindTheyAreComparedWith) {
  if (std::system(QUADMC_PEERS_PYTHON " -c 'import scipy.stats' >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << QUADMC_PEERS_PYTHON << " cannot import scipy.stats: install python3-scipy";
  }
  int checked = 0;
  for (const point_agreement& a : check_point_agreement(generators(true))) {
    if (a.peer.rfind("scipy", 0) != 0) continue;
    ++checked;
    EXPECT_TRUE(a.holds) << a.peer << ": " << a.claim << " (" << a.detail << ")";
  }
  EXPECT_EQ(checked, 4);  // Sobol and Halton, scrambled and not
}

// The timed adapters write N × s points: Boost's and GSL's first points are the sequence's
// points 1, 2, … (they skip the origin), scipy's and quadmc's start at the origin.
TEST(QmcPointPeers, EveryGeneratorWritesNTimesSCoordinatesInTheUnitCube) {
  for (const point_generator& g : generators(false)) {
    const generated_points p = g.generate(64, 3, 9, 2, true);
    ASSERT_EQ(p.x.size(), 64U * 3U) << g.name;
    EXPECT_TRUE(std::all_of(p.x.begin(), p.x.end(), [](double v) { return v >= 0.0 && v < 1.0; }))
        << g.name;
    EXPECT_GE(p.seconds, 0.0) << g.name;
  }
}

}  // namespace
}  // namespace quadmc::peers
