#pragma once
// A parking scenario: everything that, with the action sequence, determines an episode.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/parking/parking_lot.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

class Rng;

enum class LotVariant {
  Classic,  // the paper's empty, unbounded lot (the only variant comparable with the paper)
  Parked,   // parked cars in other spots and walls around the lot
};

std::string_view to_string(LotVariant variant);
// Throws InputError naming `where` for anything but "classic" or "parked".
LotVariant parse_lot_variant(std::string_view text, std::string_view where);

// Which goal spots a scenario may draw. The paper's user study used only the three rightmost spots of the
// row drawn below the start ("bottom-right": x = 18, 22, 26 m at y = +14; the reference keeps them with a
// data filter, reference-facts §1.10) because the whole lot needs many more skills than a short session
// can teach.
enum class GoalRegion {
  WholeLot,     // all 30 spots (the reference env's reset)
  StudyCorner,  // spots 12, 13, 14
};

std::string_view to_string(GoalRegion region);  // "whole-lot", "study-corner"
// Throws InputError naming `where` for anything but "whole-lot" or "study-corner".
GoalRegion parse_goal_region(std::string_view text, std::string_view where);
// The spots of the region, ascending.
std::vector<int> goal_spots(GoalRegion region);

struct ParkingScenario {
  double heading0 = 0.0;  // initial heading (rad); the car starts at (0, 0) at rest
  int goal_spot = 0;      // 0..29, reference order (see spot_pose)
  LotVariant variant = LotVariant::Classic;
  std::uint32_t obstacle_seed = 0;  // parked-car layout (ignored by the classic lot)
  bool reverse_in = false;          // goal heading flipped: the car must end nose-out (backed in)
  // Where the episode starts. Absent = the reference start: (0, 0) at rest with heading0. Drills set it
  // to the state where their first expert segment starts (teaching/tasks, Alg. 3's initial state).
  std::optional<VehicleState> start;

  bool operator==(const ParkingScenario&) const = default;
};

// The car's state at the start of the episode (the reference start unless `start` is set).
VehicleState initial_vehicle_state(const ParkingScenario& scenario);

// The goal pose: the spot centre, heading into the spot (flipped by pi for reverse-in goals).
Pose goal_pose(const ParkingScenario& scenario);
// The obstacles of the scenario's lot (empty for the classic lot).
ParkingLayout make_layout(const ParkingScenario& scenario);

// Draws a scenario like the reference's reset(): heading0 = 2*pi*U[0,1), goal spot uniform over the
// region's spots (the whole lot: all 30); then an obstacle seed, and reverse_in with the given probability
// (0 = the paper's task). Always consumes the same number of values, so neither the variant nor the region
// changes the other draws.
ParkingScenario sample_parking_scenario(Rng& rng, LotVariant variant, double reverse_in_probability = 0.0,
                                        GoalRegion region = GoalRegion::WholeLot);

}  // namespace sc
