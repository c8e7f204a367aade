#include "quadmc/sampling/warp.hpp"

#include "quadmc/sampling/disk_warps.hpp"
#include "quadmc/sampling/hemisphere_warps.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/sampling/rectangle_light_warp.hpp"

#include <gtest/gtest.h>

namespace {

using namespace quadmc;

static_assert(warp<power_warp>);
static_assert(warp<exponential_warp>);
static_assert(warp<truncated_exponential_warp>);
static_assert(warp<uniform_disk_warp>);
static_assert(warp<naive_disk_warp>);
static_assert(warp<uniform_hemisphere_warp>);
static_assert(warp<cosine_hemisphere_warp>);
static_assert(warp<rectangle_light_warp>);
static_assert(!warp<int>);

TEST(Warp, DimensionsAreStated) {
  EXPECT_EQ(uniform_hemisphere_warp{}.input_dimension(), 2u);
  EXPECT_EQ(uniform_hemisphere_warp{}.output_dimension(), 3u);
  EXPECT_EQ(power_warp(2.0).output_dimension(), 1u);
}

}  // namespace
