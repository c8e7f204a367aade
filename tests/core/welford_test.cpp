#include "quadmc/core/welford.hpp"

#include <gtest/gtest.h>

TEST(Welford, Smoke) {
  quadmc::welford w;
  for (double x : {1.0, 2.0, 3.0}) w.add(x);
  EXPECT_EQ(w.mean(), 2.0);
  EXPECT_EQ(w.variance(), 1.0);
}
