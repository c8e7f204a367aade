// Tests of sobol_points.hpp: the generator matrices against Boost's sobol_engine bit for bit, the
// (t, m, s)-net property of the points (unrandomized and after every randomization that keeps
// it), uniformity and unbiasedness of each randomization, that Owen's scramble is nested and its
// flips independent fair coins, independence of replicates, and bitwise reproducibility for any
// batch order.
#include "quadmc/sampling/sobol_points.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/sampling/sobol_blocks.hpp"
#include "sampling/uniform_bins.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>
#include <boost/random/sobol.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

namespace quadmc {
namespace {

static_assert(point_set<sobol_points<unrandomized_digits>>);
static_assert(point_set<sobol_points<owen_scramble>>);
static_assert(point_set<sobol_points<fast_owen_scramble>>);
static_assert(point_set<sobol_points<linear_matrix_scramble>>);
static_assert(point_set<sobol_points<digital_shift>>);

// Boost's sobol_engine starts at the second point of the sequence (its documentation: the
// all-zero first point is skipped) and returns the s coordinates of a point in turn, as w-bit
// integers. Our unrandomized digits are the same integers in the top 32 bits: points 1 … 2^m − 1
// must equal Boost's first 2^m − 1 outputs, and point 0 must be the origin.
TEST(SobolPoints, MatchBoostsSobolEngineBitForBitAndStartAtTheOrigin) {
  for (const std::size_t s : {1u, 2u, 5u, 40u, 1111u, 3667u}) {
    const std::uint64_t n = s > 100 ? 256 : 4096;
    const sobol_points<unrandomized_digits> ours(s, n, 0, 0);
    std::vector<std::uint64_t> digits(n * s);
    ours.generate_digits(0, digits);
    std::vector<double> x(n * s);
    ours.generate(0, x);
    for (std::size_t j = 0; j < s; ++j) {
      ASSERT_EQ(digits[j], 0u) << "s = " << s << ", dimension " << j;
      ASSERT_EQ(x[j], 0.0);
    }
    boost::random::sobol_engine<std::uint32_t, 32> boost_sobol(s);
    for (std::uint64_t i = 1; i < n; ++i) {
      for (std::size_t j = 0; j < s; ++j) {
        const std::uint32_t expected = boost_sobol();
        ASSERT_EQ(digits[i * s + j] >> 32, expected)
            << "s = " << s << ", point " << i << ", dim " << j;
        ASSERT_EQ(digits[i * s + j] & 0xffffffffu, 0u);
        ASSERT_EQ(x[i * s + j], static_cast<double>(expected) * 0x1.0p-32);
      }
    }
  }
}

TEST(SobolPoints, DropFirstPointStartsAtIndexOne) {
  const sobol_points<unrandomized_digits> all(3, 17, 0, 0);
  const sobol_points<unrandomized_digits> dropped(3, 16, 0, 0, true);
  std::vector<double> a(17 * 3), b(16 * 3);
  all.generate(0, a);
  dropped.generate(0, b);
  EXPECT_TRUE(std::equal(b.begin(), b.end(), a.begin() + 3));
}

// The t-value of the first 2^m points in s dimensions from the matrices alone (linear algebra
// over GF(2), independent of the generation code): the points are a (t, m, s)-net iff for every
// d_1 + … + d_s = m − t the first d_j rows of the m × m matrices C_j together are linearly
// independent ([Niederreiter 1992, Thm 4.28]).
unsigned rank_of(std::vector<std::uint32_t> rows) {  // rows as bit vectors of length m
  unsigned rank = 0;
  for (int bit = 31; bit >= 0; --bit) {
    const auto pivot = std::find_if(rows.begin() + rank, rows.end(),
                                    [bit](std::uint32_t r) { return ((r >> bit) & 1u) != 0; });
    if (pivot == rows.end()) continue;
    std::iter_swap(rows.begin() + rank, pivot);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (k != rank && ((rows[k] >> bit) & 1u) != 0) rows[k] ^= rows[rank];
    }
    ++rank;
  }
  return rank;
}

// Calls f(d) for every composition d_1 + … + d_s = total with d_j ≥ 0.
template <class F>
void for_each_composition(std::size_t s, unsigned total, std::vector<unsigned>& d, std::size_t j,
                          F&& f) {
  if (j + 1 == s) {
    d[j] = total;
    f(d);
    return;
  }
  for (unsigned k = 0; k <= total; ++k) {
    d[j] = k;
    for_each_composition(s, total - k, d, j + 1, f);
  }
}

unsigned t_value(const sobol_matrices& c, std::size_t s, unsigned m) {
  for (unsigned t = 0; t <= m; ++t) {
    bool net = true;
    std::vector<unsigned> d(s);
    for_each_composition(s, m - t, d, 0, [&](const std::vector<unsigned>& dims) {
      if (!net) return;
      // Row r of C_j (r < m): the bit of output digit r in each of the m columns.
      std::vector<std::uint32_t> rows;
      for (std::size_t j = 0; j < s; ++j) {
        for (unsigned r = 0; r < dims[j]; ++r) {
          std::uint32_t row = 0;
          for (unsigned k = 0; k < m; ++k) {
            row |= ((c.columns(j)[k] >> (31 - r)) & 1u) << (31 - k);
          }
          rows.push_back(row);
        }
      }
      net = rank_of(rows) == rows.size();
    });
    if (net) return t;
  }
  return m;
}

// Every elementary interval Π [a_j 2^−d_j, (a_j + 1) 2^−d_j) with Σd_j = m − t holds 2^t points.
template <class P>
bool is_net(const P& points, std::size_t s, unsigned m, unsigned t) {
  const std::uint64_t n = std::uint64_t{1} << m;
  std::vector<double> x(n * s);
  points.generate(0, x);
  bool net = true;
  std::vector<unsigned> d(s);
  for_each_composition(s, m - t, d, 0, [&](const std::vector<unsigned>& dims) {
    if (!net) return;
    std::vector<std::uint32_t> count(std::size_t{1} << (m - t), 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      std::uint64_t box = 0;
      for (std::size_t j = 0; j < s; ++j) {
        const auto a =
            static_cast<std::uint64_t>(std::ldexp(x[i * s + j], static_cast<int>(dims[j])));
        box = (box << dims[j]) | a;
      }
      ++count[box];
    }
    net = std::all_of(count.begin(), count.end(),
                      [t](std::uint32_t c) { return c == (std::uint32_t{1} << t); });
  });
  return net;
}

template <class R>
class SobolNet : public ::testing::Test {};
using net_preserving = ::testing::Types<unrandomized_digits, owen_scramble, fast_owen_scramble,
                                        linear_matrix_scramble, digital_shift>;
TYPED_TEST_SUITE(SobolNet, net_preserving);

// Owen's nested scrambling, its hash approximation (each digit a bijection depending only on
// the digits before it), the linear matrix scramble (L invertible lower triangular) and the
// digital shift all map elementary intervals to elementary intervals of the same shape, so the
// net property of the unrandomized points must survive each of them, for every seed.
TYPED_TEST(SobolNet, EveryElementaryIntervalHoldsTwoToTheTPoints) {
  for (const std::size_t s : {2u, 3u, 5u, 8u}) {
    const sobol_matrices c(s);
    for (const unsigned m : {4u, 7u, 10u}) {
      const unsigned t = t_value(c, s, m);
      if (s == 2) {
        EXPECT_EQ(t, 0u) << "Sobol' points are (0, m, 2)-nets";
      }
      for (std::uint64_t seed : {1u, 2u}) {
        const sobol_points<TypeParam> points(s, std::uint64_t{1} << m, seed, 9);
        EXPECT_TRUE(is_net(points, s, m, t)) << "s = " << s << ", m = " << m << ", t = " << t;
        if (t > 0) {
          // The t found is the smallest: the property fails at t − 1 for the unrandomized set
          // (and for the randomizations, which keep each interval's count).
          EXPECT_FALSE(is_net(points, s, m, t - 1)) << "s = " << s << ", m = " << m;
        }
      }
    }
  }
}

// Unbiasedness: the mean over R = 400 independent randomizations of a 64-point estimate of
// ∫ Π(3x_j² ) = 1 over [0,1]^3 lies within t(1 − 5e-5, R − 1)·s_R/√R of 1: a false alarm of 1e-4
// per randomization under the t approximation (R = 400 replicates of a bounded estimate).
template <class R>
class SobolUnbiased : public ::testing::Test {};
using randomized =
    ::testing::Types<owen_scramble, fast_owen_scramble, linear_matrix_scramble, digital_shift>;
TYPED_TEST_SUITE(SobolUnbiased, randomized);

TYPED_TEST(SobolUnbiased, ReplicateMeanIsWithinItsStandardError) {
  constexpr std::size_t s = 3;
  constexpr std::uint64_t n = 64;
  constexpr int R = 400;
  std::vector<double> values;
  std::vector<double> x(n * s);
  for (int r = 0; r < R; ++r) {
    const sobol_points<TypeParam> points(s, n, 77, static_cast<std::uint64_t>(r));
    points.generate(0, x);
    double sum = 0.0;
    for (std::uint64_t i = 0; i < n; ++i) {
      double f = 1.0;
      for (std::size_t j = 0; j < s; ++j) f *= 3.0 * x[i * s + j] * x[i * s + j];
      sum += f;
    }
    values.push_back(sum / static_cast<double>(n));
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / R;
  double m2 = 0.0;
  for (double v : values) m2 += (v - mean) * (v - mean);
  const double se = std::sqrt(m2 / (R - 1) / R);
  const double t = boost::math::quantile(boost::math::students_t(R - 1), 1.0 - 5e-5);
  EXPECT_LE(std::abs(mean - 1.0), t * se) << "mean " << mean << ", se " << se;
  EXPECT_GT(se, 0.0) << "a randomization that changes nothing";
}

// Every coordinate of a randomized point is uniform on [0, 1): point i = 5 in dimension 3, over
// 4096 randomizations (test_support::expect_uniform_over_streams states the bound).
TYPED_TEST(SobolUnbiased, EachRandomizedCoordinateIsUniform) {
  std::vector<double> x(3);
  test_support::expect_uniform_over_streams([&](std::uint64_t r) {
    sobol_points<TypeParam>(3, 8, 5, r).generate(5, x);
    return x[2];
  });
}

// Replicates are independent: different streams give different points, and over 400 pairs of
// streams the correlation of the two estimates' errors is within 4.4/√400 of 0 (its standard
// deviation is about 1/√n under independence: a false alarm of 1e-5).
TEST(SobolPoints, ReplicatesOfDifferentStreamsAreIndependent) {
  constexpr int pairs = 400;
  std::vector<double> a, b;
  std::vector<double> x(32 * 2);
  auto estimate = [&](std::uint64_t stream) {
    const sobol_points<owen_scramble> p(2, 32, 3, stream);
    p.generate(0, x);
    double sum = 0.0;
    for (int i = 0; i < 32; ++i) sum += std::exp(x[2 * i] * x[2 * i + 1]);
    return sum / 32.0;
  };
  for (int k = 0; k < pairs; ++k) {
    a.push_back(estimate(2 * static_cast<std::uint64_t>(k)));
    b.push_back(estimate(2 * static_cast<std::uint64_t>(k) + 1));
  }
  EXPECT_NE(a[0], b[0]);
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / pairs;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / pairs;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (int k = 0; k < pairs; ++k) {
    sab += (a[k] - ma) * (b[k] - mb);
    saa += (a[k] - ma) * (a[k] - ma);
    sbb += (b[k] - mb) * (b[k] - mb);
  }
  EXPECT_LE(std::abs(sab / std::sqrt(saa * sbb)), 4.4 / std::sqrt(pairs));
}

// Counter-based keys: the same (seed, stream) gives bitwise the same points in any batch order.
TYPED_TEST(SobolNet, BatchOrderDoesNotChangeAnyBit) {
  const std::size_t s = 4;
  const std::uint64_t n = 1000;
  const sobol_points<TypeParam> p(s, n, 5, 6);
  std::vector<double> whole(n * s), pieces(n * s);
  p.generate(0, whole);
  for (std::uint64_t end = n; end > 0;) {
    const std::uint64_t size = std::min<std::uint64_t>(end, 1 + end % 37);
    p.generate(end - size, std::span<double>(pieces).subspan((end - size) * s, size * s));
    end -= size;
  }
  EXPECT_EQ(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(double)), 0);
  const sobol_points<TypeParam> again(s, n, 5, 6);
  std::vector<double> twice(n * s);
  again.generate(0, twice);
  EXPECT_EQ(std::memcmp(whole.data(), twice.data(), whole.size() * sizeof(double)), 0);
}

// The vector kernel (sampling/sobol_blocks.hpp) against the scalar Gray-code walk kept as
// generate_reference: bitwise equal for every randomization, dimensions on both sides of the
// block sizes (s ≤ 8: 8/gcd(s, 8) points per block; above: 64-lane slices, 16 with AVX2, with a
// masked tail), N up to 2^16 and windows up to 2^20, the first point dropped or not, the last
// indices below 2^32, and
// batches cut at sizes and starts that split blocks anywhere; at every simd level this CPU offers.
template <class R>
void expect_kernel_equals_reference(std::size_t s, std::uint64_t n, bool drop_first,
                                    std::uint64_t first = 0) {
  const sobol_points<R> points(s, n, 2026, 18, drop_first);
  const std::uint64_t count = std::min<std::uint64_t>(n - first, std::uint64_t{1} << 20);
  std::vector<double> reference(count * s);
  points.generate_reference(first, reference);
  for (const simd_level level : available_simd_levels()) {
    // At the avx512 level, both builds of the kernel: with GFNI where the CPU has it, and the
    // plain one a CPU without GFNI runs.
    for (const bool gfni : {true, false}) {
      if (!gfni && level != simd_level::avx512) continue;
      set_simd_level(level);
      quadmc::detail::allow_sobol_gfni(gfni);
      const std::string where = "s = " + std::to_string(s) + ", N = " + std::to_string(n) +
                                ", level " + std::string(to_string(level)) +
                                (gfni ? "" : " without GFNI");
      std::vector<double> whole(count * s);
      points.generate(first, whole);
      ASSERT_EQ(std::memcmp(whole.data(), reference.data(), whole.size() * sizeof(double)), 0)
          << "one batch, " << where;
      // Batches of 1, 7, 256, 1000 and 3 points in turn: starts at every residue mod 8.
      std::vector<double> split(count * s, -1.0);
      const std::uint64_t sizes[] = {1, 7, 256, 1000, 3};
      for (std::uint64_t p = 0, k = 0; p < count; ++k) {
        const std::uint64_t c = std::min(sizes[k % 5], count - p);
        points.generate(first + p, std::span<double>(split.data() + p * s, c * s));
        p += c;
      }
      ASSERT_EQ(std::memcmp(split.data(), reference.data(), split.size() * sizeof(double)), 0)
          << "split batches, " << where;
    }
  }
  quadmc::detail::allow_sobol_gfni(true);
}

template <class R>
void expect_kernel_equals_reference_for_all_sizes() {
  const simd_level saved = active_simd_level();
  for (const std::size_t s : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 13u, 64u, 65u, 130u}) {
    const std::uint64_t n = s == 1 ? std::uint64_t{1} << 16 : s <= 8 ? 1u << 13 : 1u << 12;
    expect_kernel_equals_reference<R>(s, n, false);
    expect_kernel_equals_reference<R>(s, n - 1, true);
  }
  // Columns 13 … 20: windows of 6000 points across 2^17 and 2^20, whose first points set those
  // columns' bits (the kernel's direct start) and whose walk flips column 17 or 20 once.
  for (const std::size_t s : {1u, 5u}) {
    for (const unsigned top : {17u, 20u}) {
      expect_kernel_equals_reference<R>(s, (std::uint64_t{1} << top) + 3000, false,
                                        (std::uint64_t{1} << top) - 3000);
    }
  }
  // The top of the index range: columns 20 … 31 and a block index near 2^29.
  expect_kernel_equals_reference<R>(3, std::uint64_t{1} << 32, false,
                                    (std::uint64_t{1} << 32) - 5000);
  expect_kernel_equals_reference<R>(2, (std::uint64_t{1} << 32) - 1, true,
                                    (std::uint64_t{1} << 32) - 1 - 5000);
  expect_kernel_equals_reference<R>(3667, 64, false);
  set_simd_level(saved);
}

TEST(SobolPoints, VectorKernelEqualsTheScalarWalkBitwise) {
  expect_kernel_equals_reference_for_all_sizes<unrandomized_digits>();
  expect_kernel_equals_reference_for_all_sizes<digital_shift>();
  expect_kernel_equals_reference_for_all_sizes<linear_matrix_scramble>();
  expect_kernel_equals_reference_for_all_sizes<fast_owen_scramble>();
  expect_kernel_equals_reference_for_all_sizes<owen_scramble>();
}

// Owen's scramble is nested: the flip of digit b (0-based) is a function of the digits before it
// alone, so two inputs that share their first b digits are flipped alike in digits 0 … b, for
// every b, whatever their later digits (here depth 32, the tree's six-level hashes on every
// level and the tail below).
TEST(OwenScramble, FlipOfADigitDependsOnlyOnTheDigitsBeforeIt) {
  const owen_scramble scramble(1, 32, random_stream(11, 3));
  std::uint64_t state = 2026;
  for (int trial = 0; trial < 2000; ++trial) {
    const std::uint64_t v = mix64(state++) << 32;
    for (unsigned b = 0; b < 32; ++b) {
      // Keep digits 0 … b − 1, replace digits b … 31 by others.
      const std::uint64_t keep = b == 0 ? 0 : ~std::uint64_t{0} << (64 - b);
      const std::uint64_t w = (v & keep) | ((mix64(state++) << 32) & ~keep);
      const std::uint64_t flips_v = scramble(v, 0) ^ v;
      const std::uint64_t flips_w = scramble(w, 0) ^ w;
      const std::uint64_t through_b = ~std::uint64_t{0} << (63 - b);
      ASSERT_EQ(flips_v & through_b, flips_w & through_b) << "digit " << b;
    }
  }
}

// Nested *uniform*: the flips of the tree's nodes are independent fair coins. Over R = 20000
// seeds (the keys sobol_points draws), each of 59 nodes on levels 0 … 13 flips with frequency
// 1/2, and each of the 362 pairs of nodes on one level or adjacent levels (parent and child in
// one six-level hash, siblings, the two sides of a hash boundary, nodes of different subtrees,
// the prefix table's last level and the first hashed one) has x ⊕ y with frequency 1/2, which
// for fair coins is their independence. Each count is Binomial(R, 1/2) under the claim;
// |count − R/2| ≤ 5.3·√R/2 fails with probability 1.2e-7 per count, 4.9e-5 for the 421 counts.
TEST(OwenScramble, NodeFlipsAreIndependentFairCoins) {
  constexpr int R = 20000;
  // A node: a prefix of `length` digits (as the top digits of a word), flipping digit `length`.
  struct node {
    std::uint64_t digits;
    unsigned length;
  };
  const auto flip = [](std::uint64_t seed, node n) {
    const std::uint64_t v = n.length == 0 ? 0 : n.digits << (64 - n.length);
    return (owen_scramble::flips(seed, v, 0, n.length + 1) >> (63 - n.length)) & 1;
  };
  std::vector<node> nodes;
  for (unsigned length = 0; length <= 13; ++length) {
    for (const std::uint64_t digits : {0ull, 1ull, 5ull, 0x2aull, 0x1555ull}) {
      const std::uint64_t d = length == 0 ? 0 : digits & ((std::uint64_t{1} << length) - 1);
      const bool seen = std::any_of(nodes.begin(), nodes.end(), [&](const node& n) {
        return n.length == length && n.digits == d;
      });
      if (!seen) nodes.push_back({d, length});
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    for (std::size_t b = a + 1; b < nodes.size(); ++b) {
      const int gap = static_cast<int>(nodes[b].length) - static_cast<int>(nodes[a].length);
      if (gap >= 0 && gap <= 1) pairs.emplace_back(a, b);  // same or adjacent levels
    }
  }
  ASSERT_EQ(nodes.size(), 59u);  // the counts the false-alarm bound above is stated for
  ASSERT_EQ(pairs.size(), 362u);
  std::vector<int> ones(nodes.size(), 0), differ(pairs.size(), 0);
  std::vector<std::uint64_t> x(nodes.size());
  for (int r = 0; r < R; ++r) {
    const std::uint64_t seed =
        owen_scramble(1, 14, random_stream(31, static_cast<std::uint64_t>(r))).key(0);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      ones[i] += static_cast<int>(x[i] = flip(seed, nodes[i]));
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      differ[p] += static_cast<int>(x[pairs[p].first] ^ x[pairs[p].second]);
    }
  }
  const double bound = 5.3 * std::sqrt(static_cast<double>(R)) / 2.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_LE(std::abs(ones[i] - R / 2), bound) << "level " << nodes[i].length;
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    EXPECT_LE(std::abs(differ[p] - R / 2), bound)
        << "levels " << nodes[pairs[p].first].length << " and " << nodes[pairs[p].second].length;
  }
}

TEST(SobolPoints, RejectsWhatTheTableCannotGive) {
  EXPECT_THROW(sobol_points<owen_scramble>(3668, 4, 0, 0), invalid_argument);
  EXPECT_THROW(sobol_points<owen_scramble>(1, (std::uint64_t{1} << 32) + 1, 0, 0),
               invalid_argument);
  EXPECT_THROW(sobol_points<owen_scramble>(1, std::uint64_t{1} << 32, 0, 0, true),
               invalid_argument);
  EXPECT_THROW(sobol_points<owen_scramble>(2, 0, 0, 0), invalid_argument);
}

}  // namespace
}  // namespace quadmc
