// Test support: whether one coordinate of a randomized point set is uniform on [0, 1), over
// independent randomizations (streams 0 … 4095): the count in each of 16 equal bins must lie
// within 4.9 standard deviations of 256 (binomial, p = 1/16, sd = 15.5: a false alarm of 1e-6
// per bin, 1.6e-5 for the 16).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace quadmc::test_support {

// coordinate(stream) is the coordinate under test in the set randomized by that stream.
template <class Coordinate>
void expect_uniform_over_streams(Coordinate&& coordinate) {
  constexpr std::uint64_t streams = 4096;
  std::vector<int> bins(16, 0);
  for (std::uint64_t r = 0; r < streams; ++r) {
    ++bins[static_cast<std::size_t>(coordinate(r) * 16)];
  }
  const double sd = std::sqrt(4096.0 * (1.0 / 16) * (15.0 / 16));
  for (int b = 0; b < 16; ++b) EXPECT_NEAR(bins[b], 256.0, 4.9 * sd) << "bin " << b;
}

}  // namespace quadmc::test_support
