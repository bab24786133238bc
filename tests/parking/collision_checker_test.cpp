// Car-versus-obstacle overlap with Box2D, including the polygon-skin correction, and the sim's response.
#include "engine/parking/collision_checker.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/parking/parking_sim.hpp"

namespace sc {
namespace {

ParkingLayout one_parked_car() {
  ParkingLayout layout;
  layout.parked_cars.push_back({10.0, 0.0, 0.0, 2.5, 1.0});  // spans x 7.5..12.5, y -1..1
  return layout;
}

TEST(CollisionChecker, EmptyLayoutNeverCollides) {
  const CollisionChecker checker(ParkingLayout{});
  EXPECT_FALSE(checker.has_obstacles());
  EXPECT_FALSE(checker.car_collides({0.0, 0.0, 0.0, 0.0}));
}

TEST(CollisionChecker, GapsAndOverlapsAlongTheCarAxis) {
  const CollisionChecker checker(one_parked_car());
  // Our car's front bumper is at x + 2.5; the obstacle's rear at 7.5.
  EXPECT_FALSE(
      checker.car_collides({5.0 - 0.015, 0.0, 0.0, 0.0}));  // 1.5 cm gap: Box2D's raw skin would report contact
  EXPECT_FALSE(checker.car_collides({5.0 - 0.003, 0.0, 0.0, 0.0}));
  EXPECT_TRUE(checker.car_collides({5.0 + 0.003, 0.0, 0.0, 0.0}));  // 3 mm of overlap
  EXPECT_TRUE(checker.car_collides({10.0, 0.0, 1.0, 0.0}));         // right on top, rotated
}

TEST(CollisionChecker, SideBySideInNeighbouringSpots) {
  const CollisionChecker checker(one_parked_car());
  EXPECT_FALSE(checker.car_collides({10.0, 2.02, 0.0, 0.0}));  // 2 cm apart, parallel
  EXPECT_TRUE(checker.car_collides({10.0, 1.98, 0.0, 0.0}));
}

TEST(CollisionChecker, RotatedCornerTouchesOnlyWhenItReachesTheSide) {
  const CollisionChecker checker(one_parked_car());
  // Car turned by 90 degrees above the obstacle: its half extent along y is 2.5, so the lowest point is at
  // y - 2.5; the obstacle's top side is at y = 1.
  const double up = std::numbers::pi / 2;
  EXPECT_FALSE(checker.car_collides({10.0, 3.52, up, 0.0}));
  EXPECT_TRUE(checker.car_collides({10.0, 3.48, up, 0.0}));
  // Rotated by 45 degrees, the lowest corner is (2.5 + 1)/sqrt(2) = 2.4749 below the centre.
  const double diag = 3.5 / std::sqrt(2.0);
  EXPECT_FALSE(checker.car_collides({10.0, 1.0 + diag + 0.01, std::numbers::pi / 4, 0.0}));
  EXPECT_TRUE(checker.car_collides({10.0, 1.0 + diag - 0.01, std::numbers::pi / 4, 0.0}));
}

TEST(ParkingSimCollision, HittingAWallEndsTheEpisodeWithThePenalty) {
  // Parked lot, heading +x along the empty aisle: the right wall's inner face is at x = 32.
  ParkingScenario s;
  s.variant = LotVariant::Parked;
  s.obstacle_seed = 5;
  s.goal_spot = 0;
  ParkingSim sim(s);
  ParkingStepResult r;
  int steps = 0;
  do {
    r = sim.step({1.0, 0.0});
    ++steps;
  } while (!r.done);
  EXPECT_TRUE(r.collision);
  EXPECT_FALSE(r.success);
  EXPECT_TRUE(sim.collided());
  EXPECT_LT(steps, 100);
  EXPECT_NEAR(r.reward, parking_reward(sim.observation()) - 5.0, 1e-12);
  EXPECT_EQ(sim.vehicle().speed, 0.0);
  // Stopped at the first sub-step that overlaps: the front bumper is past the wall face by less than
  // one sub-step of travel (speed < 20 m/s -> < 1.4 m).
  EXPECT_GE(sim.vehicle().x + 2.5, 32.0);
  EXPECT_LT(sim.vehicle().x + 2.5, 33.4);
}

TEST(ParkingSimCollision, ClassicLotIgnoresTheObstacleSeed) {
  ParkingScenario s;
  s.obstacle_seed = 5;
  ParkingSim sim(s);
  EXPECT_TRUE(sim.layout().empty());
  for (int t = 0; t < 30; ++t) EXPECT_FALSE(sim.step({1.0, 0.0}).collision);
  EXPECT_GT(sim.vehicle().x, 33.0);
}

}  // namespace
}  // namespace sc
