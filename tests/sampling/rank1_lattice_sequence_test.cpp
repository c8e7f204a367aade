// The extensible lattice in radical-inverse order (sampling/rank1_lattice_sequence.hpp): its
// first 2^m points are the 2^m-point lattice of rank1_lattice_points, bit for bit.
#include "quadmc/sampling/rank1_lattice_sequence.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace quadmc {
namespace {

TEST(Rank1LatticeSequence, RadicalInverseReversesTheBits) {
  EXPECT_EQ(radical_inverse_bits(0), 0U);
  EXPECT_EQ(radical_inverse_bits(1), 0x80000000U);
  EXPECT_EQ(radical_inverse_bits(2), 0x40000000U);
  EXPECT_EQ(radical_inverse_bits(3), 0xC0000000U);
  EXPECT_EQ(radical_inverse_bits(0x80000000U), 1U);
  EXPECT_EQ(radical_inverse_bits(0x12345678U), 0x1E6A2C48U);
}

// Point q of the sequence is point bitrev_m(q) of the 2^m lattice, for every m it fits in.
template <class Periodization>
void expect_prefixes_are_lattices(std::size_t s, bool shifted) {
  const std::uint64_t cap = 1U << 12;
  const rank1_lattice_sequence<Periodization> sequence(s, cap, 7, 3, shifted);
  std::vector<double> all(cap * s);
  sequence.generate(0, all);
  for (const unsigned m : {0U, 1U, 5U, 12U}) {
    const std::uint64_t n = std::uint64_t{1} << m;
    const rank1_lattice_points<Periodization> lattice(s, n, 7, 3, shifted);
    std::vector<double> points(n * s);
    lattice.generate_reference(0, points);
    for (std::uint64_t q = 0; q < n; ++q) {
      const std::uint64_t i =
          m == 0 ? 0 : radical_inverse_bits(static_cast<std::uint32_t>(q)) >> (32 - m);
      for (std::size_t j = 0; j < s; ++j) {
        ASSERT_EQ(all[q * s + j], points[i * s + j])
            << "m = " << m << ", q = " << q << ", j = " << j;
      }
    }
  }
}

TEST(Rank1LatticeSequence, PrefixesAreTheLatticesOfRank1LatticePoints) {
  expect_prefixes_are_lattices<no_periodization>(5, true);
  expect_prefixes_are_lattices<no_periodization>(3, false);
  expect_prefixes_are_lattices<baker_transform>(4, true);
}

TEST(Rank1LatticeSequence, BatchesAnywhereGiveTheSamePoints) {
  const rank1_lattice_sequence<no_periodization> sequence(3, 1024, 1, 2);
  std::vector<double> whole(1024 * 3);
  sequence.generate(0, whole);
  std::vector<double> part(100 * 3);
  sequence.generate(517, part);
  for (std::size_t k = 0; k < part.size(); ++k) EXPECT_EQ(part[k], whole[517 * 3 + k]);
}

TEST(Rank1LatticeSequence, RefusesWhatTheGeneratingVectorCannotHold) {
  EXPECT_THROW(rank1_lattice_sequence<no_periodization>(2, 1000, 1, 1), invalid_argument);
  EXPECT_THROW(rank1_lattice_sequence<no_periodization>(2, std::uint64_t{1} << 21, 1, 1),
               invalid_argument);
  EXPECT_THROW(rank1_lattice_sequence<no_periodization>(3601, 1024, 1, 1), invalid_argument);
}

}  // namespace
}  // namespace quadmc
