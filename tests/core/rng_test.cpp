#include "engine/core/rng.hpp"

#include <gtest/gtest.h>

namespace sc {

TEST(Rng, SameSeedSameSequence) {
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
  EXPECT_NE(Rng(42).next_u64(), c.next_u64());
}

TEST(Rng, BelowStaysInRangeAndCoversIt) {
  Rng r(7);
  int seen[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 1000; ++i) seen[r.below(5)]++;
  for (int count : seen) EXPECT_GT(count, 150);
}

TEST(Rng, ForkedStreamsDifferAndAreStable) {
  Rng base(1);
  EXPECT_EQ(base.fork(3).next_u64(), base.fork(3).next_u64());
  EXPECT_NE(base.fork(3).next_u64(), base.fork(4).next_u64());
}

}  // namespace sc
