// Tests for core/summation.hpp: compensated (Neumaier) and pairwise summation against naive
// recursive summation, on the Basel series Σ_{k=1}^{n} 1/k² added in increasing k (large terms
// first, the bad order for naive summation: late terms fall below half an ulp of the running sum
// and are rounded away or, between ulp/2 and ulp, rounded up to a whole ulp, all with one sign).
//
// Reference: the exact sum of the doubles actually added, computed once in cpp_bin_float_50 (50
// decimal digits) as
//   Σ_{k=1}^{n} 1/k² = π²/6 − ψ'(n+1)                      (DLMF 25.11.1 with 5.15.1: ψ'(z) =
//                                                           Σ_{k≥0} 1/(k+z)²)
//   + Σ_{k=1}^{K} (fl(1/k²) − 1/k²)                        (rounding of the terms themselves)
// with K = 10⁴. For k ≤ K, k² is exact and fl(1/k²) carries one rounding, corrected exactly here;
// for K < k ≤ n the terms carry at most two roundings (k² ≥ 2^53 past k ≈ 9.49·10⁷), so the
// neglected part is below (2u + u²)·Σ_{k>K} 1/k² < 2.0001·u/K ≈ 2.2e-20 ≈ 1e-4 ulp of the sum
// (u = 2^-53). Boost's trigamma in 50 digits is accurate to a few units of 1e-50. So the
// reference is exact to well under 0.001 ulp, which is all the ulp counts below need; summing
// 10⁸ terms in multiprecision instead would take minutes.
#include "quadmc/core/summation.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;

using quadmc::test_support::unit_roundoff;  // u = 2^-53

double basel_term(std::uint64_t k) {
  const double d = static_cast<double>(k);
  return 1.0 / (d * d);
}

// Exact (to < 0.001 ulp) sum of basel_term(1) + … + basel_term(n); see the file comment.
mp basel_reference(std::uint64_t n) {
  constexpr std::uint64_t corrected_terms = 10'000;
  mp sum = boost::math::constants::pi_sqr_div_six<mp>() - boost::math::trigamma(mp(n + 1));
  for (std::uint64_t k = 1; k <= corrected_terms && k <= n; ++k) {
    const mp kk(k);
    sum += mp(basel_term(k)) - 1 / (kk * kk);
  }
  return sum;
}

// Spacing of doubles at `reference` (2^-52 for sums in [1, 2)).
double ulp_at(const mp& reference) {
  const double r = static_cast<double>(reference);
  return std::nextafter(r, std::numeric_limits<double>::infinity()) - r;
}

double error_in_ulps(double value, const mp& reference) {
  return std::abs(static_cast<double>((mp(value) - reference) / ulp_at(reference)));
}

// 10⁸ terms, streamed: generated in blocks of 4096 into one buffer (no 800 MB vector, which an
// ASan run on CI could not afford), fed term by term to neumaier_sum and to naive addition in the
// same increasing-k order. pairwise_sum needs the whole span to build its tree, so it is tested on
// 10⁷ terms held in memory (80 MB) below; building a tree of block sums here would test our
// tree, not pairwise_sum.
TEST(NeumaierSum, BaselSeriesOfOneHundredMillionTermsIsWithinTwoUlp) {
  constexpr std::uint64_t n = 100'000'000;
  constexpr std::size_t block = 4096;
  std::vector<double> buffer(block);
  quadmc::neumaier_sum compensated;
  double naive = 0.0;
  for (std::uint64_t first = 1; first <= n; first += block) {
    const std::size_t count =
        static_cast<std::size_t>(std::min<std::uint64_t>(block, n + 1 - first));
    for (std::size_t i = 0; i < count; ++i) buffer[i] = basel_term(first + i);
    for (std::size_t i = 0; i < count; ++i) compensated.add(buffer[i]);
    for (std::size_t i = 0; i < count; ++i) naive += buffer[i];
  }
  const mp reference = basel_reference(n);
  const double compensated_ulps = error_in_ulps(compensated.value(), reference);
  const double naive_ulps = error_in_ulps(naive, reference);

  // Higham (2002) §4.3: compensated summation errs by at most (2u + O(n·u²))·Σ|x_i|; here
  // Σ|x_i| ≈ 1.645 and ulp = 2u, so 2u·Σ|x_i| ≈ 1.65 ulp, and n·u² ≈ 1e-24 is negligible.
  EXPECT_LE(compensated_ulps, 2.0) << "neumaier_sum over n = " << n << " terms";
  // The same terms added naively lose millions of ulp (about 4.4e6 measured): the test proves
  // the difference, it is not an accident of easy data.
  EXPECT_GE(naive_ulps, 1000.0 * std::max(compensated_ulps, 2.0))
      << "naive summation over n = " << n << ", compensated error " << compensated_ulps << " ulp";
}

TEST(PairwiseSum, BaselSeriesOfTenMillionTermsIsWithinItsErrorBound) {
  constexpr std::size_t n = 10'000'000;
  std::vector<double> terms(n);
  for (std::size_t k = 0; k < n; ++k) terms[k] = basel_term(k + 1);
  const mp reference = basel_reference(n);

  const double pairwise_ulps = error_in_ulps(quadmc::pairwise_sum(terms), reference);
  const double naive_ulps = error_in_ulps(quadmc::naive_sum(terms), reference);
  quadmc::neumaier_sum compensated;
  for (const double t : terms) compensated.add(t);
  const double compensated_ulps = error_in_ulps(compensated.value(), reference);

  // Higham (2002) §4.2: pairwise summation errs by at most depth·u·Σ|x_i| (first order), depth
  // = additions on the longest leaf-to-root path. pairwise_sum halves down to leaves of ≤ 128
  // terms (⌈log2(n/128)⌉ + 1 levels, one extra for the rounding of the split to a multiple of
  // 128) and each leaf adds 16 terms per accumulator (15 roundings) and joins 8 accumulators (3
  // levels): 17 + 1 + 18 = 36 levels for n = 10⁷, a bound of 36·u·1.645 ≈ 30 ulp. Measured:
  // 3.1 ulp.
  const int levels = std::bit_width((n + 127) / 128) + 1 + 18;
  const double pairwise_bound_ulps =
      levels * unit_roundoff * static_cast<double>(reference) / ulp_at(reference);
  EXPECT_LE(pairwise_ulps, pairwise_bound_ulps) << "pairwise_sum over n = " << n;
  EXPECT_LE(compensated_ulps, 2.0) << "neumaier_sum over n = " << n;
  // Naive summation errs by 4377 ulp on these 10⁷ terms: over 1000 times what both others do.
  EXPECT_GE(naive_ulps, 1000.0 * std::max(pairwise_ulps, compensated_ulps))
      << "naive " << naive_ulps << " ulp, pairwise " << pairwise_ulps << " ulp, compensated "
      << compensated_ulps << " ulp, n = " << n;

  // Chunks summed apart and merged in order (what parallel_reduce does with chunk sums): each
  // chunk errs by ≤ 2u·|chunk sum| and the merge adds ≤ 2u·Σ|chunk sums|, so ≤ 4u·Σ|x_i| ≈ 3.3 ulp.
  quadmc::neumaier_sum merged;
  std::size_t begin = 0;
  for (std::size_t size = 1; begin < n; size = size * 3 + 7) {
    const std::size_t end = std::min(n, begin + size);
    quadmc::neumaier_sum chunk;
    for (std::size_t k = begin; k < end; ++k) chunk.add(terms[k]);
    merged.merge(chunk);
    begin = end;
  }
  EXPECT_LE(error_in_ulps(merged.value(), reference),
            4 * unit_roundoff * static_cast<double>(reference) / ulp_at(reference))
      << "neumaier_sum merged from uneven chunks, n = " << n;
}

TEST(NeumaierSum, KeepsSmallTermsWhenALargeTermArrives) {
  // Neumaier's improvement over Kahan: when |x| > |sum| the lost bits are those of the sum. Kahan
  // and naive summation both return 0 here; the exact sum is 2.
  quadmc::neumaier_sum s;
  for (const double x : {1.0, 1e100, 1.0, -1e100}) s += x;
  EXPECT_EQ(s.value(), 2.0);
  EXPECT_EQ(quadmc::naive_sum(std::vector<double>{1.0, 1e100, 1.0, -1e100}), 0.0);

  EXPECT_EQ(quadmc::neumaier_sum().value(), 0.0);
  EXPECT_EQ(quadmc::neumaier_sum(3.5).value(), 3.5);

  // Merging keeps both compensations: (1 + 1e100) merged with (1 − 1e100) is exactly 2.
  quadmc::neumaier_sum a;
  a.add(1.0);
  a.add(1e100);
  quadmc::neumaier_sum b;
  b.add(1.0);
  b.add(-1e100);
  a.merge(b);
  EXPECT_EQ(a.value(), 2.0);
}

TEST(PairwiseSum, AddsEveryTermExactlyOnceForEverySize) {
  // Small integers add exactly in any order, so any size at which the leaf loop or the split
  // drops or repeats a term shows up as a wrong integer. Sizes cover the leaf (≤ 128), the
  // unrolled tail (n mod 8), the split of 129…255 and deeper trees.
  std::vector<double> x(70'000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i + 1);
  std::vector<std::size_t> sizes;
  for (std::size_t n = 0; n <= 1100; ++n) sizes.push_back(n);
  for (const std::size_t n : {4095, 4096, 4097, 65'535, 65'536, 70'000}) sizes.push_back(n);
  for (const std::size_t n : sizes) {
    const double expected = static_cast<double>(n) * static_cast<double>(n + 1) / 2;
    ASSERT_EQ(quadmc::pairwise_sum(std::span(x).first(n)), expected) << "n = " << n;
    ASSERT_EQ(quadmc::naive_sum(std::span(x).first(n)), expected) << "n = " << n;
  }
}

// The accumulator names are the scene key's values (parse.hpp `accumulator`): each spelling maps
// back to its enumerator, and anything else is refused (nullopt), never a silent default.
TEST(Summation, PolicyNamesRoundTrip) {
  using quadmc::summation;
  for (summation s :
       {summation::pairwise, summation::neumaier, summation::naive, summation::long_double}) {
    EXPECT_EQ(quadmc::parse_summation(quadmc::to_string(s)), s) << quadmc::to_string(s);
  }
  EXPECT_EQ(quadmc::to_string(summation::long_double), "long_double");
  EXPECT_FALSE(quadmc::parse_summation("kahan").has_value());
  EXPECT_FALSE(quadmc::parse_summation("").has_value());
  EXPECT_FALSE(quadmc::parse_summation("Naive").has_value());
  static_assert(quadmc::parse_summation("neumaier") == summation::neumaier);
}

}  // namespace
