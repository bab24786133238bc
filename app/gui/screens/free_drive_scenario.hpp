#pragma once
// What the free-drive screen lets the learner pick: a seed (the scenario drawn from it like the reference's
// reset), the lot variant, reverse-in goals, and optionally a fixed goal spot.
#include <cstdint>
#include <string>

#include "engine/parking/parking_scenario.hpp"

namespace sc {

struct FreeDriveScenarioChoice {
  std::uint64_t seed = 1;
  LotVariant variant = LotVariant::Classic;
  bool reverse_in = false;
  int goal_spot = -1;  // -1: the seed's spot; 0..29: this spot

  bool operator==(const FreeDriveScenarioChoice&) const = default;
};

// Deterministic: same choice, same scenario.
ParkingScenario make_free_drive_scenario(const FreeDriveScenarioChoice& choice);

// "spot 7: upper row, 6 m right of the start" - for the goal list.
std::string describe_spot(int spot);

}  // namespace sc
