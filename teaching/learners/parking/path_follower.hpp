#pragma once
// A driver who watches the expert's path and steers back to it, for realistic drivers that close the loop.
//
// Why. Replayed open loop, a noisy, delayed or keyed copy of the expert's drive drifts and nobody corrects
// it: the car ends somewhere else, almost never parks, and its motion is no longer the expert's, so a
// skill model that reads the motion rightly gives it other skills. A learner in the app sees the ghost path
// and corrects; a skill model should give such a drive the expert's skills, quantised keys and all.
//
// Spec. The expert's drive is re-simulated sub-step by sub-step (1/15 s; the bicycle model without
// obstacles). For a car seen in state `seen` that should be where the expert was at sub-step j, the
// correction is the (du0, du1) of a fixed grid (each axis -1, -0.5, -0.2, 0, 0.2, 0.5, 1) that, added to
// the expert's actions of sub-steps j .. j + H - 1 (clipped to [-1, 1]) and held, brings the car closest
// to the expert's state at sub-step j + H, H = kFollowerHorizonSubsteps (0.6 s: a driver's look ahead at
// parking speed). Closeness: squared position error (m^2) + (half a car length x heading error)^2 +
// (H x speed error)^2, plus 0.01 |du|^2 so that a car on the path keeps the expert's action exactly.
// Past the expert's end the expert stands still with no input. Ties go to the earlier grid point (0 first).
// Deterministic; no randomness.
#include <vector>

#include "engine/parking/parking_trial.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

inline constexpr int kFollowerHorizonSubsteps = 9;  // 0.6 s at 15 Hz

class PathFollower {
 public:
  // `expert` at the control rate (control_hz 5); its actions are held for 3 sub-steps each.
  explicit PathFollower(const ParkingTrial& expert);

  // The correction to add to the expert's action of sub-step j for a car seen in `seen` (j < 0 counts as 0).
  ParkingAction correction(const VehicleState& seen, int substep) const;

  // The expert's state at the start of sub-step j (clamped to the drive's end).
  const VehicleState& expert_state(int substep) const;
  int substeps() const { return static_cast<int>(actions_.size()); }

 private:
  ParkingAction expert_action(int substep) const;
  double miss(const VehicleState& seen, int substep, const ParkingAction& delta) const;

  std::vector<VehicleState> states_;    // substeps() + 1: before each sub-step, and after the last
  std::vector<ParkingAction> actions_;  // the expert's clipped action of each sub-step
};

// How much room a follower has: the expert's control steps whose pedal or steering is at its limit
// (|u| >= kAtLimit after clipping), where no correction can add to what the expert already asks.
inline constexpr double kAtLimit = 0.99;
struct ActuatorLimits {
  int steps = 0;
  int pedal = 0;     // |u0| at the limit
  int steering = 0;  // |u1| at the limit
};
ActuatorLimits actions_at_limits(const std::vector<ParkingTrial>& drives);

}  // namespace sc
