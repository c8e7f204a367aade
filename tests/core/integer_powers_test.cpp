// Tests of integer_powers.hpp: exact powers and roots, where pow() would round.
#include "quadmc/core/integer_powers.hpp"

#include <gtest/gtest.h>

namespace quadmc {
namespace {

TEST(CheckedPower, ExactUpToTheLimitAndNulloptBeyond) {
  EXPECT_EQ(checked_power(2, 63), std::uint64_t{1} << 63);
  EXPECT_EQ(checked_power(2, 64), std::nullopt);
  EXPECT_EQ(checked_power(4294967295u, 2), 18446744065119617025u);  // (2^32 − 1)^2
  EXPECT_EQ(checked_power(4294967296u, 2), std::nullopt);
  EXPECT_EQ(checked_power(0, 5), 0u);
  EXPECT_EQ(checked_power(7, 0), 1u);
  // With a limit: 10^3 = 1000 fits 1000, not 999.
  EXPECT_EQ(checked_power(10, 3, 1000), 1000u);
  EXPECT_EQ(checked_power(10, 3, 999), std::nullopt);
  static_assert(checked_power(3, 4) == 81u);
}

TEST(IntegerRoot, ExactAroundEveryPerfectPowerForSUpTo8) {
  for (unsigned s = 1; s <= 8; ++s) {
    for (std::uint64_t q = 1; q <= 200; ++q) {
      const auto p = checked_power(q, s);
      if (!p) break;
      EXPECT_EQ(integer_root(*p, s), q) << "s = " << s << ", N = " << q << "^" << s;
      EXPECT_EQ(integer_root(*p - 1, s), q - 1) << "s = " << s << ", N = " << q << "^s − 1";
      // q^s + 1 < (q+1)^s for s ≥ 2; for s = 1 it is (q+1)^1.
      EXPECT_EQ(integer_root(*p + 1, s), s == 1 ? q + 1 : q)
          << "s = " << s << ", N = " << q << "^s + 1";
    }
  }
  // The largest 64-bit value: its square root is 2^32 − 1 exactly (pow would round to 2^32).
  EXPECT_EQ(integer_root(18446744073709551615u, 2), 4294967295u);
  EXPECT_EQ(integer_root(18446744073709551615u, 64), 1u);
  EXPECT_EQ(integer_root(4096, 3), 16u) << "pow(4096, 1/3.) = 15.999…";
  EXPECT_EQ(integer_root(0, 3), 0u);
  EXPECT_EQ(integer_root(5, 0), 0u);
}

}  // namespace
}  // namespace quadmc
