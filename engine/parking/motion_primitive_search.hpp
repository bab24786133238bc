#pragma once
// Initial guesses for the expert's optimiser: a small tree of two-phase motion primitives (drive forward
// or back with a fixed steering for a few steps, then forward or back with another steering), simulated
// with the real model and collision test. Each primitive is scored by the best weighted goal distance it
// reaches, and the best of each manoeuvre class (first direction, first turn side, second direction) is
// kept, so the optimiser starts from topologically different manoeuvres.
#include <vector>

#include "engine/parking/collision_checker.hpp"
#include "engine/parking/parking_scenario.hpp"

namespace sc {

struct ManoeuvreGuess {
  std::vector<ParkingAction> actions;  // up to the step of the best score
  double score = 0.0;                  // weighted goal distance (success below 0.0144)
};

// Best guesses for reaching `target` (scored with the reward's weighted distance), lowest score first,
// at most `keep`; `max_steps` bounds each primitive.
std::vector<ManoeuvreGuess> search_manoeuvres(const ParkingScenario& scenario, const CollisionChecker& collisions,
                                              const Pose& target, int max_steps, int keep);

}  // namespace sc
