#pragma once
// A short simulated parking drive for the tests of how drives are read: `standing` control steps with the pedal
// at `idle_pedal`, then `manoeuvres` times forward with a left turn and back on the pedal to a stop (12 steps
// each), then `standing_after` steps of standing still.
#include <vector>

#include "engine/parking/parking_sim.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc::test {

inline StepSequence parking_test_drive(int standing, double idle_pedal = 0.0, int standing_after = 0,
                                       int manoeuvres = 1) {
  ParkingSim sim(parking_pool_scenario(0, 0));
  std::vector<ParkingObservation> states{sim.observation()};
  std::vector<ParkingAction> actions;
  for (int i = 0; i < standing; ++i) actions.push_back({idle_pedal, 0.0});
  for (int m = 0; m < manoeuvres; ++m) {
    for (int i = 0; i < 6; ++i) actions.push_back({0.9, 0.4});
    for (int i = 0; i < 6; ++i) actions.push_back({-0.9, -0.4});
  }
  for (int i = 0; i < standing_after; ++i) actions.push_back({0.0, 0.0});
  for (const ParkingAction& u : actions) {
    sim.step(u);
    states.push_back(sim.observation());
  }
  return parking_step_sequence(states, actions);
}

}  // namespace sc::test
