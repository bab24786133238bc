#pragma once
// A parking episode driven live, one 1/15 s simulation sub-step at a time, for screens that show the car
// moving smoothly while the learner (or the expert, as a demonstration) drives.
//
// ParkingSim advances a whole 0.2 s control step at once; drawing only its states would make the car jump
// five times a second. LiveParkingDrive keeps the car's sub-step state with the very same update and
// collision rule, feeds the live input through the ActionLatch (latched every 0.2 s, or responsive), and
// hands each completed control step to ParkingSim, which stays the authority for reward, success and
// collision. What it records (to_trial) replays to exactly the same episode.
#include <array>
#include <vector>

#include "engine/input/action_latch.hpp"
#include "engine/parking/parking_sim.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/car_painter.hpp"

namespace sc {

class LiveParkingDrive {
 public:
  explicit LiveParkingDrive(const ParkingScenario& scenario, input::ActionTiming timing = input::ActionTiming::Latched);

  // One simulation sub-step with the device's live action. Does nothing once done().
  void substep(const input::DriveAction& live);

  const ParkingScenario& scenario() const { return sim_.scenario(); }
  const ParkingLayout& layout() const { return sim_.layout(); }
  const Pose& goal() const { return sim_.goal(); }
  // The car before and after the last sub-step (draw between them with interpolate_car_pose).
  const VehicleState& previous() const { return previous_; }
  const VehicleState& current() const { return current_; }
  double steering() const { return steering_; }  // rad, of the last sub-step
  CarPose pose(double alpha) const;
  // The action applied in the last sub-step (what the car obeys, as opposed to the live input).
  const input::DriveAction& applied_action() const { return applied_; }
  // Car positions at every sub-step, the start included.
  const std::vector<Vec2f>& trail() const { return trail_; }

  std::int64_t substeps() const { return latch_.substeps_done(); }
  double time_seconds() const { return static_cast<double>(substeps()) * parking::kDt; }
  int control_steps() const { return sim_.steps(); }
  // Reward of the car where it is now (updated every sub-step, for the live readout); the episode's
  // rewards are those of completed control steps.
  double live_reward() const;
  const std::vector<double>& rewards() const { return rewards_; }
  double total_return() const;
  bool done() const { return sim_.done(); }
  bool succeeded() const { return sim_.succeeded(); }
  bool collided() const { return sim_.collided(); }

  // The recorded trial (actions as applied; source/device as given). Latched: one action per control step
  // (control_hz 5); responsive: one per sub-step (control_hz 15).
  ParkingTrial to_trial(const std::string& source, const std::string& device) const;

 private:
  ParkingSim sim_;
  CollisionChecker collisions_;
  input::ActionLatch latch_;
  std::array<ParkingAction, parking::kSubstepsPerAction> pending_{};
  int pending_count_ = 0;
  bool crashed_in_step_ = false;
  VehicleState previous_;
  VehicleState current_;
  double steering_ = 0.0;
  input::DriveAction applied_;
  std::vector<Vec2f> trail_;
  std::vector<ParkingObservation> states_;
  std::vector<double> rewards_;
};

}  // namespace sc
