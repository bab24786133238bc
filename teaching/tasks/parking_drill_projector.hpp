#pragma once
// Parking drills made playable (Alg. 3's projection back to trajectory space): the drill starts in the
// car state where its first expert segment starts, the segments' expert actions are concatenated and
// re-simulated from there in ParkingSim against the goal of the LAST segment's expert scenario. The ghost
// path is what the simulator produced, so it is continuous by construction and the app's replay of the
// drill trial reproduces it exactly. The episode ends early when the car parks (ParkingSim semantics);
// the steps then stop there.
#include <vector>

#include "engine/parking/parking_trial.hpp"
#include "teaching/drills/drill_plan.hpp"

namespace sc {

class ParkingDrillProjector final : public DrillProjector {
 public:
  // experts[i]: the pool's expert trial i (with T+1 states); DrillSegment::expert indexes this list.
  explicit ParkingDrillProjector(std::vector<ParkingTrial> experts);

  // steps: 12-D observations against the drill's goal; ghost_path: car centre (m) per state;
  // drill_return: the last step's reward (the reference's episode score, like reward_of); success: the
  // car parked at the last segment's goal. InputError for a bad plan (see concatenate_expert_steps).
  PlayableDrill project(const DrillPlan& plan) const override;

  // The scenario a drill is played in: the last segment's expert scenario starting at the drill's
  // initial state (heading0 set to the start heading too).
  ParkingScenario drill_scenario(const DrillPlan& plan) const;
  // The drill as a parking trial (source "drill"): its scenario, the executed actions, states, rewards.
  ParkingTrial drill_trial(const PlayableDrill& drill) const;

 private:
  std::vector<ParkingAction> drill_actions(const DrillPlan& plan) const;  // segments' expert actions, in order

  std::vector<ParkingTrial> experts_;
  std::vector<StepSequence> expert_steps_;
};

}  // namespace sc
