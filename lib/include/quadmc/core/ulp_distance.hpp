// How many doubles lie between two doubles: the distance in units in the last place (ulp) that
// accuracy bounds are stated in (e.g. "vector exp within 5 ulp of scalar exp", vector_math.hpp).
//
// Method: the IEEE-754 bits of a double, read as a sign-magnitude integer and mapped to two's
// complement, are ordered like the doubles themselves (Dawson, "Comparing floating point numbers",
// 2012), so the difference of the mapped integers counts the doubles in between. +0 and −0 are
// 0 apart; the smallest subnormals of opposite sign are 2 apart. Not for NaN (no order).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace quadmc {

constexpr std::uint64_t ulp_distance(double a, double b) noexcept {
  auto ordered = [](double v) {
    const auto bits = std::bit_cast<std::int64_t>(v);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t ia = ordered(a), ib = ordered(b);
  return ia > ib ? static_cast<std::uint64_t>(ia) - static_cast<std::uint64_t>(ib)
                 : static_cast<std::uint64_t>(ib) - static_cast<std::uint64_t>(ia);
}

}  // namespace quadmc
