#include "engine/parking/parking_scenario.hpp"

#include <numbers>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace sc {

std::string_view to_string(LotVariant variant) { return variant == LotVariant::Parked ? "parked" : "classic"; }

LotVariant parse_lot_variant(std::string_view text, std::string_view where) {
  if (text == "classic") return LotVariant::Classic;
  if (text == "parked") return LotVariant::Parked;
  throw InputError(where, "unknown lot variant \"" + std::string(text) + "\" (expected \"classic\" or \"parked\")");
}

std::string_view to_string(GoalRegion region) {
  return region == GoalRegion::StudyCorner ? "study-corner" : "whole-lot";
}

GoalRegion parse_goal_region(std::string_view text, std::string_view where) {
  if (text == "whole-lot") return GoalRegion::WholeLot;
  if (text == "study-corner") return GoalRegion::StudyCorner;
  throw InputError(where,
                   "unknown goal region \"" + std::string(text) + "\" (expected \"whole-lot\" or \"study-corner\")");
}

std::vector<int> goal_spots(GoalRegion region) {
  if (region == GoalRegion::StudyCorner) return {12, 13, 14};
  std::vector<int> all(parking::kSpotCount);
  for (int k = 0; k < parking::kSpotCount; ++k) all[static_cast<std::size_t>(k)] = k;
  return all;
}

Pose goal_pose(const ParkingScenario& scenario) {
  Pose goal = spot_pose(scenario.goal_spot);
  if (scenario.reverse_in) goal.heading = -goal.heading;  // +-pi/2 flipped by pi
  return goal;
}

ParkingLayout make_layout(const ParkingScenario& scenario) {
  if (scenario.variant == LotVariant::Classic) return {};
  return make_parked_layout(scenario.obstacle_seed, scenario.goal_spot);
}

ParkingScenario sample_parking_scenario(Rng& rng, LotVariant variant, double reverse_in_probability,
                                        GoalRegion region) {
  ParkingScenario s;
  s.heading0 = 2.0 * std::numbers::pi * rng.uniform();
  const std::vector<int> spots = goal_spots(region);
  s.goal_spot = spots[static_cast<std::size_t>(rng.below(spots.size()))];
  s.variant = variant;
  s.obstacle_seed = static_cast<std::uint32_t>(rng.next_u64() >> 32);
  s.reverse_in = rng.uniform() < reverse_in_probability;
  return s;
}

VehicleState initial_vehicle_state(const ParkingScenario& scenario) {
  return scenario.start ? *scenario.start : VehicleState{0.0, 0.0, scenario.heading0, 0.0};
}

}  // namespace sc
