// Scenario sampling, lot geometry and the parked-car layouts.
#include "engine/parking/parking_scenario.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/collision_checker.hpp"
#include "engine/parking/parking_sim.hpp"

namespace sc {
namespace {

TEST(ParkingLot, SpotsFollowTheReferenceOrder) {
  EXPECT_EQ(spot_pose(0).x, -30.0);
  EXPECT_EQ(spot_pose(0).y, 14.0);
  EXPECT_DOUBLE_EQ(spot_pose(0).heading, std::numbers::pi / 2);
  EXPECT_EQ(spot_pose(14).x, 26.0);
  EXPECT_EQ(spot_pose(15).x, -30.0);
  EXPECT_EQ(spot_pose(15).y, -14.0);
  EXPECT_DOUBLE_EQ(spot_pose(29).heading, -std::numbers::pi / 2);
  EXPECT_EQ(spot_pose(3).x, -18.0);  // the golden episode's goal
  EXPECT_THROW(spot_pose(30), std::out_of_range);
  const auto lines = spot_lines(15);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].x0, -32.0);
  EXPECT_EQ(lines[0].y0, -10.0);
  EXPECT_EQ(lines[0].y1, -18.0);
  EXPECT_EQ(lines[1].x0, -28.0);
}

TEST(ParkingScenario, SamplingCoversTheRangesAndIsDeterministic) {
  Rng a(42), b(42);
  bool rows[2] = {false, false};
  for (int i = 0; i < 200; ++i) {
    const ParkingScenario s = sample_parking_scenario(a, LotVariant::Classic);
    EXPECT_EQ(s, sample_parking_scenario(b, LotVariant::Classic));
    EXPECT_GE(s.heading0, 0.0);
    EXPECT_LT(s.heading0, 2.0 * std::numbers::pi);
    ASSERT_GE(s.goal_spot, 0);
    ASSERT_LT(s.goal_spot, 30);
    rows[s.goal_spot / 15] = true;
    EXPECT_FALSE(s.reverse_in);
  }
  EXPECT_TRUE(rows[0] && rows[1]);
}

TEST(ParkingScenario, VariantDoesNotChangeHeadingsAndGoals) {
  Rng a(7), b(7);
  for (int i = 0; i < 20; ++i) {
    ParkingScenario c = sample_parking_scenario(a, LotVariant::Classic);
    const ParkingScenario p = sample_parking_scenario(b, LotVariant::Parked);
    c.variant = LotVariant::Parked;
    EXPECT_EQ(c, p);
  }
}

TEST(ParkingScenario, StudyCornerDrawsOnlyTheThreeBottomRightSpotsAndKeepsTheOtherDraws) {
  EXPECT_EQ(goal_spots(GoalRegion::StudyCorner), (std::vector<int>{12, 13, 14}));
  EXPECT_EQ(goal_spots(GoalRegion::WholeLot).size(), 30u);
  for (int spot : goal_spots(GoalRegion::StudyCorner)) {
    EXPECT_GE(spot_pose(spot).x, 18.0);
    EXPECT_EQ(spot_pose(spot).y, 14.0);  // the row drawn below the start
  }
  Rng a(11), b(11);
  int seen[3] = {0, 0, 0};
  for (int i = 0; i < 300; ++i) {
    const ParkingScenario whole = sample_parking_scenario(a, LotVariant::Classic);
    const ParkingScenario corner = sample_parking_scenario(b, LotVariant::Classic, 0.0, GoalRegion::StudyCorner);
    ASSERT_GE(corner.goal_spot, 12);
    ASSERT_LE(corner.goal_spot, 14);
    ++seen[corner.goal_spot - 12];
    EXPECT_EQ(corner.heading0, whole.heading0);
    EXPECT_EQ(corner.obstacle_seed, whole.obstacle_seed);
  }
  for (int n : seen) EXPECT_GT(n, 60);
}

TEST(ParkingScenario, GoalRegionNamesRoundTripAndBadNamesAreInputErrors) {
  for (GoalRegion r : {GoalRegion::WholeLot, GoalRegion::StudyCorner})
    EXPECT_EQ(parse_goal_region(to_string(r), "test"), r);
  EXPECT_THROW(parse_goal_region("bottom-right", "test"), InputError);
}

TEST(ParkingScenario, ReverseInProbability) {
  Rng rng(3);
  int reversed = 0;
  for (int i = 0; i < 1000; ++i) reversed += sample_parking_scenario(rng, LotVariant::Classic, 0.5).reverse_in;
  EXPECT_GT(reversed, 430);
  EXPECT_LT(reversed, 570);
}

TEST(ParkingScenario, ParsesVariantNames) {
  EXPECT_EQ(parse_lot_variant("parked", "x"), LotVariant::Parked);
  EXPECT_EQ(to_string(LotVariant::Classic), "classic");
  try {
    parse_lot_variant("busy", "--variant");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--variant: unknown lot variant \"busy\" (expected \"classic\" or \"parked\")");
  }
}

// Hash of the exact bits of the state after 40 steps of a fixed open-loop policy on 20 sampled scenarios
// of each variant: any change in sampling, layout, dynamics or collision handling changes it.
std::uint64_t rollout_hash(LotVariant variant) {
  Rng rng(2024);
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](double v) {
    h ^= std::bit_cast<std::uint64_t>(v);
    h *= 1099511628211ULL;
  };
  for (int i = 0; i < 20; ++i) {
    ParkingSim sim(sample_parking_scenario(rng, variant, 0.3));
    for (int t = 0; t < 40 && !sim.done(); ++t) {
      const ParkingStepResult r = sim.step({std::sin(0.3 * t + i), std::cos(0.2 * t) * 0.8});
      mix(r.reward);
    }
    for (double v : sim.observation()) mix(v);
    mix(sim.steps());
  }
  return h;
}

TEST(ParkingScenario, RolloutsAreDeterministic) {
  EXPECT_EQ(rollout_hash(LotVariant::Classic), rollout_hash(LotVariant::Classic));
  EXPECT_EQ(rollout_hash(LotVariant::Parked), rollout_hash(LotVariant::Parked));
  EXPECT_NE(rollout_hash(LotVariant::Classic), rollout_hash(LotVariant::Parked));
  // Recorded on Debian 12 / x86-64 (glibc libm); a change means the episodes changed.
  EXPECT_EQ(rollout_hash(LotVariant::Classic), 5344807722451695584u);
  EXPECT_EQ(rollout_hash(LotVariant::Parked), 594056954067651719u);
}

TEST(ParkedLayout, LeavesTheGoalFreeAndKeepsCarsInsideTheirSpots) {
  for (std::uint32_t seed = 0; seed < 300; ++seed) {
    const int goal = static_cast<int>(seed % 30);
    const ParkingLayout layout = make_parked_layout(seed, goal);
    ASSERT_EQ(layout.walls.size(), 4u);
    EXPECT_GE(layout.parked_cars.size(), 5u);
    EXPECT_LE(layout.parked_cars.size(), 27u);
    const Pose g = spot_pose(goal);
    for (const auto& car : layout.parked_cars) {
      EXPECT_GT(std::fabs(car.x - g.x) + std::fabs(car.y - g.y), 3.0) << "seed " << seed;
      // Every corner stays within the spot lines (x_k +- 2) and the spot depth (|y| in 10..18).
      const double c = std::cos(car.heading), s = std::sin(car.heading);
      const double spot_x = 4.0 * std::round((car.x + 2.0) / 4.0) - 2.0;
      for (double u : {-2.5, 2.5})
        for (double w : {-1.0, 1.0}) {
          const double x = car.x + u * c - w * s, y = car.y + u * s + w * c;
          EXPECT_LT(std::fabs(x - spot_x), 2.0);
          EXPECT_GT(std::fabs(y), 10.0);
          EXPECT_LT(std::fabs(y), 18.0);
        }
    }
    // The goal pose itself and the start pose (any heading) are collision-free.
    const CollisionChecker checker(layout);
    EXPECT_FALSE(checker.car_collides({g.x, g.y, g.heading, 0.0}));
    for (double h = 0.0; h < 6.3; h += 0.5) EXPECT_FALSE(checker.car_collides({0.0, 0.0, h, 0.0}));
  }
}

}  // namespace
}  // namespace sc
