// Test support: the double-precision constants and bit patterns that tolerances and bitwise
// comparisons are written in. One definition for every test file, so that the files of one test
// executable can be compiled together (tests/CMakeLists.txt, QUADMC_UNITY_TESTS).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace quadmc::test_support {

// Machine epsilon 2^-52, and the unit roundoff u = eps/2 = 2^-53 of round-to-nearest
// (docs/theory.md#rounding-floor).
inline constexpr double eps = std::numeric_limits<double>::epsilon();
inline constexpr double unit_roundoff = eps / 2;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The bits of v: bitwise equality, with -0.0 != 0.0 and every NaN payload told apart.
inline std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

}  // namespace quadmc::test_support
