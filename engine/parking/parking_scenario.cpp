#include "engine/parking/parking_scenario.hpp"

#include <numbers>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace sc {

std::string_view to_string(LotVariant variant) {
  return variant == LotVariant::Parked ? "parked" : "classic";
}

LotVariant parse_lot_variant(std::string_view text, std::string_view where) {
  if (text == "classic") return LotVariant::Classic;
  if (text == "parked") return LotVariant::Parked;
  throw InputError(where, "unknown lot variant \"" + std::string(text) + "\" (expected \"classic\" or \"parked\")");
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

ParkingScenario sample_parking_scenario(Rng& rng, LotVariant variant, double reverse_in_probability) {
  ParkingScenario s;
  s.heading0 = 2.0 * std::numbers::pi * rng.uniform();
  s.goal_spot = static_cast<int>(rng.below(parking::kSpotCount));
  s.variant = variant;
  s.obstacle_seed = static_cast<std::uint32_t>(rng.next_u64() >> 32);
  s.reverse_in = rng.uniform() < reverse_in_probability;
  return s;
}

VehicleState initial_vehicle_state(const ParkingScenario& scenario) {
  return scenario.start ? *scenario.start : VehicleState{0.0, 0.0, scenario.heading0, 0.0};
}

}  // namespace sc
