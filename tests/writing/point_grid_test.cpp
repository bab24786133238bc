#include "engine/writing/point_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/rng.hpp"

namespace sc::writing {
namespace {

double brute_nearest(const std::vector<Point2>& points, const Point2& q) {
  double best = INFINITY;
  for (const Point2& p : points)
    best = std::min(best, std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y)));
  return best;
}

TEST(PointGrid, TheNearestPointWithinTheCellIsFoundExactlyAndNoneBeyondIt) {
  Rng rng(3);
  std::vector<Point2> points;
  for (int i = 0; i < 400; ++i) points.push_back({rng.uniform(-50, 150), rng.uniform(-20, 80)});
  const PointGrid grid(points, 8.0);
  for (int k = 0; k < 2000; ++k) {
    const Point2 q{rng.uniform(-70, 170), rng.uniform(-40, 100)};
    const double truth = brute_nearest(points, q);
    const double found = grid.nearest(q, 0.0);
    if (truth <= 8.0)
      EXPECT_EQ(found, truth) << k;
    else
      EXPECT_TRUE(std::isinf(found)) << k;
  }
}

TEST(PointGrid, StopsAtAPointWithinGoodEnough) {
  const std::vector<Point2> points{{0, 0}, {1, 0}, {0.1, 0}};
  const PointGrid grid(points, 8.0);
  EXPECT_LE(grid.nearest({0.2, 0}, 3.0), 3.0);
  EXPECT_DOUBLE_EQ(grid.nearest({0.2, 0}, 0.0), 0.1);
  EXPECT_TRUE(std::isinf(PointGrid({}, 8.0).nearest({0, 0}, 3.0)));
}

}  // namespace
}  // namespace sc::writing
