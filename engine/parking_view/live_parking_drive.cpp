#include "engine/parking_view/live_parking_drive.hpp"

#include <numeric>

#include "engine/parking_view/parking_path.hpp"

namespace sc {
namespace {

Vec2f position(const VehicleState& v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

}  // namespace

LiveParkingDrive::LiveParkingDrive(const ParkingScenario& scenario, input::ActionTiming timing)
    : sim_(scenario), collisions_(sim_.layout()), latch_(timing) {
  previous_ = current_ = sim_.vehicle();
  trail_.push_back(position(current_));
  states_.push_back(sim_.observation());
}

void LiveParkingDrive::substep(const input::DriveAction& live) {
  if (sim_.done()) return;
  applied_ = latch_.next_substep(live);
  const ParkingAction u = clip_action({applied_.accel, applied_.steer});
  pending_[static_cast<std::size_t>(pending_count_++)] = u;
  previous_ = current_;
  // The same sub-step ParkingSim will compute; a crashed car stays put for the rest of the control step.
  if (!crashed_in_step_) {
    steering_ = steering_of(u);
    current_ = bicycle_substep(current_, acceleration_of(u), steering_);
    if (collisions_.has_obstacles() && collisions_.car_collides(current_)) {
      current_.speed = 0.0;
      crashed_in_step_ = true;
    }
  }
  if (pending_count_ == parking::kSubstepsPerAction) {
    const ParkingStepResult result = sim_.step_substeps(pending_);
    rewards_.push_back(result.reward);
    states_.push_back(sim_.observation());
    current_ = sim_.vehicle();  // identical by construction; ParkingSim stays the single authority
    pending_count_ = 0;
    crashed_in_step_ = false;
  }
  trail_.push_back(position(current_));
}

CarPose LiveParkingDrive::pose(double alpha) const {
  return interpolate_car_pose(previous_, current_, steering_, alpha);
}

double LiveParkingDrive::live_reward() const { return parking_reward(make_observation(current_, sim_.goal())); }

double LiveParkingDrive::total_return() const { return std::accumulate(rewards_.begin(), rewards_.end(), 0.0); }

ParkingTrial LiveParkingDrive::to_trial(const std::string& source, const std::string& device) const {
  ParkingTrial trial;
  trial.scenario = sim_.scenario();
  const auto& recorded = latch_.recorded();
  const bool responsive = recorded.substeps_per_action == 1;
  trial.control_hz = responsive ? parking::kSimulationHz : parking::kControlHz;
  // Only completed control steps: a half-finished one cannot be replayed the way it was shown.
  const std::size_t count = static_cast<std::size_t>(sim_.steps()) * (responsive ? parking::kSubstepsPerAction : 1);
  for (std::size_t i = 0; i < count && i < recorded.actions.size(); ++i)
    trial.actions.push_back({recorded.actions[i].accel, recorded.actions[i].steer});
  trial.states = states_;
  trial.rewards = rewards_;
  trial.success = sim_.succeeded();
  trial.source = source;
  trial.device = device;
  return trial;
}

}  // namespace sc
