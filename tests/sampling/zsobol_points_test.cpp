// Tests of sampling/zsobol_points.hpp: the Morton code, the digit permutation (a bijection that
// keeps every aligned block of indices aligned), the nets a pixel, a Morton tile and the whole
// image form, uniform coordinates over streams, and the refusals.
#include "quadmc/sampling/zsobol_points.hpp"

#include "elementary_intervals.hpp"
#include "uniform_bins.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace quadmc {
namespace {

using test_support::is_pair_net;

TEST(ZsobolPoints, MortonInterleavesColumnBitsEvenAndRowBitsOdd) {
  EXPECT_EQ(zsobol_points::morton(0, 0), 0u);
  EXPECT_EQ(zsobol_points::morton(1, 0), 1u);
  EXPECT_EQ(zsobol_points::morton(0, 1), 2u);
  EXPECT_EQ(zsobol_points::morton(3, 3), 15u);
  EXPECT_EQ(zsobol_points::morton(4, 0), 16u);
  EXPECT_EQ(zsobol_points::morton(5, 6), 0b111001u);  // c = 101, r = 110
  EXPECT_EQ(zsobol_points::morton(32767, 32767), (std::uint64_t{1} << 30) - 1);
}

// For T = 2R + k even and odd (spp 4 and 8 on 8 × 8 pixels, and 2 on 4 × 4): every index once,
// and each aligned block of a pixel's or a Morton tile's indices onto an aligned block of the
// same size.
TEST(ZsobolPoints, ThePermutationIsABijectionKeepingAlignedBlocks) {
  for (const auto& [side, spp] : {std::pair<std::size_t, std::uint64_t>{8, 4}, {8, 8}, {4, 2}}) {
    const zsobol_points z(side, side, spp, 3, 7);
    const std::uint64_t n = std::uint64_t{1} << z.index_bits();
    std::vector<std::uint64_t> image(n);
    for (std::uint64_t m = 0; m < n; ++m) image[m] = z.permuted_index(m);
    std::vector<std::uint64_t> sorted = image;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint64_t m = 0; m < n; ++m) ASSERT_EQ(sorted[m], m) << "T = " << z.index_bits();
    // Digits are base 4 from the top, so the blocks kept are those of 2^b with b ≡ T (mod 2):
    // the pixel's 2^k (T = 2R + k) and the tiles' 4^j·2^k among them.
    for (unsigned b = z.index_bits() % 2 == 0 ? 2 : 1; b <= z.index_bits(); b += 2) {
      const std::uint64_t block = std::uint64_t{1} << b;
      for (std::uint64_t first = 0; first < n; first += block) {
        const std::uint64_t base = image[first] & ~(block - 1);
        for (std::uint64_t m = first; m < first + block; ++m) {
          ASSERT_EQ(image[m] & ~(block - 1), base) << "block " << first << " of " << block;
        }
      }
    }
    // Random: not the identity (a fixed permutation of the 24 would be the same on every seed).
    EXPECT_NE(image, [&] {
      std::vector<std::uint64_t> identity(n);
      for (std::uint64_t m = 0; m < n; ++m) identity[m] = m;
      return identity;
    }());
  }
}

std::vector<double> pixel_points(const zsobol_points& z, std::size_t c, std::size_t r) {
  std::vector<double> u(2 * z.samples_per_pixel());
  z.generate(c, r, u);
  return u;
}

// A pixel's 2^k points are a (0, k, 2)-net; the 4 pixels of an aligned 2 × 2 tile together a
// (0, k + 2, 2)-net, and all 16 × 16 pixels of the image a (0, 8 + k, 2)-net: neighbours share
// one net, which is what makes their errors cancel.
TEST(ZsobolPoints, PixelsTilesAndTheImageAreNets) {
  for (const std::uint64_t spp : {1u, 2u, 4u, 16u}) {
    const zsobol_points z(16, 16, spp, 11, 2);
    const auto k = static_cast<unsigned>(std::countr_zero(spp));
    std::vector<double> all;
    for (std::size_t r = 0; r < 16; ++r) {
      for (std::size_t c = 0; c < 16; ++c) {
        const std::vector<double> u = pixel_points(z, c, r);
        EXPECT_TRUE(is_pair_net(u, 2, 0, 1, 0, k)) << "pixel " << c << ", " << r;
        all.insert(all.end(), u.begin(), u.end());
      }
    }
    EXPECT_TRUE(is_pair_net(all, 2, 0, 1, 0, 8 + k)) << "spp " << spp;
    for (std::size_t r = 0; r < 16; r += 2) {
      for (std::size_t c = 0; c < 16; c += 2) {
        std::vector<double> tile;
        for (const auto& [dc, dr] :
             {std::pair<std::size_t, std::size_t>{0, 0}, {1, 0}, {0, 1}, {1, 1}}) {
          const std::vector<double> u = pixel_points(z, c + dc, r + dr);
          tile.insert(tile.end(), u.begin(), u.end());
        }
        EXPECT_TRUE(is_pair_net(tile, 2, 0, 1, 0, k + 2)) << "tile " << c << ", " << r;
      }
    }
  }
}

// A non-square image of a side that is no power of two: the pixels it has still take disjoint
// blocks of the 32 × 32 square's sequence, so together they are points of one net, none twice.
TEST(ZsobolPoints, ImagesOfAnySizeTakeDisjointBlocks) {
  const zsobol_points z(20, 7, 4, 1, 1);
  EXPECT_EQ(z.index_bits(), 2u * 5u + 2u);
  std::vector<double> all;
  for (std::size_t r = 0; r < 7; ++r) {
    for (std::size_t c = 0; c < 20; ++c) {
      const std::vector<double> u = pixel_points(z, c, r);
      all.insert(all.end(), u.begin(), u.end());
    }
  }
  // Distinct points of a (0, 12, 2)-net: no two in one of the 2^12 boxes of 2^−6 × 2^−6.
  std::vector<std::uint8_t> box(std::size_t{1} << 12, 0);
  for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
    const auto b =
        static_cast<std::size_t>(all[i] * 64) * 64 + static_cast<std::size_t>(all[i + 1] * 64);
    EXPECT_EQ(++box[b], 1) << "point " << i / 2;
  }
}

// Over 4096 streams, each coordinate of a pixel's first point is uniform (the scramble makes
// every point uniform); bound and false-alarm rate in uniform_bins.hpp.
TEST(ZsobolPoints, CoordinatesAreUniformOverStreams) {
  for (const std::size_t d : {0u, 1u}) {
    test_support::expect_uniform_over_streams([d](std::uint64_t stream) {
      const zsobol_points z(8, 8, 4, 2026, stream);
      return pixel_points(z, 5, 3)[d];
    });
  }
}

TEST(ZsobolPoints, RefusesWhatItCannotIndex) {
  EXPECT_THROW(zsobol_points(8, 8, 3, 0, 0), invalid_argument);          // spp not 2^k
  EXPECT_THROW(zsobol_points(0, 8, 4, 0, 0), invalid_argument);          // no pixel
  EXPECT_THROW(zsobol_points(32769, 8, 4, 0, 0), invalid_argument);      // side above 2^15
  EXPECT_THROW(zsobol_points(4096, 4096, 512, 0, 0), invalid_argument);  // 2·12 + 9 > 32
  EXPECT_NO_THROW(zsobol_points(4096, 4096, 256, 0, 0));                 // 2·12 + 8 = 32
  const zsobol_points z(4, 3, 2, 0, 0);
  std::vector<double> u(4);
  EXPECT_THROW(z.generate(4, 0, u), invalid_argument);
  EXPECT_THROW(z.generate(0, 3, u), invalid_argument);
  std::vector<double> short_out(2);
  EXPECT_THROW(z.generate(0, 0, short_out), invalid_argument);
}

}  // namespace
}  // namespace quadmc
