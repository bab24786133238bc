#pragma once
// A driven path at the simulation's 15 Hz resolution, for drawing: trails, ghost ribbons and ghost cars.
// The 5 Hz control states are too coarse to draw (a car at 8 m/s moves 1.6 m per control step), so paths are
// re-simulated sub-step by sub-step with the very bicycle update and collision rule of ParkingSim.
#include <span>
#include <vector>

#include "engine/parking/parking_sim.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/car_painter.hpp"

namespace sc {

struct PathSample {
  double t = 0.0;         // seconds since the start of the episode
  VehicleState vehicle;   // after the sub-step (the first sample is the start state)
  double steering = 0.0;  // rad, applied during the sub-step that led here (0 for the start)
};

struct ParkingPath {
  std::vector<PathSample> samples;  // at least the start sample
  int control_steps = 0;            // control steps simulated (ParkingSim::steps())
  std::vector<double> rewards;      // one per control step
  int success_step = -1;            // 1-based, -1 when never reached
  bool collision = false;

  double duration() const { return samples.empty() ? 0.0 : samples.back().t; }
};

// Simulates `actions` from the scenario until the episode ends or the actions run out. control_hz = 5: one
// action per 0.2 s control step (held for 3 sub-steps); control_hz = 15: one action per sub-step (the
// "responsive" recording), as in ParkingTrial. Actions left over after the episode ended are ignored, like
// `skillcoach replay`. Every control step's end state equals what ParkingSim reports (checked by tests).
ParkingPath simulate_parking_path(const ParkingScenario& scenario, std::span<const ParkingAction> actions,
                                  int control_hz = parking::kControlHz);
ParkingPath simulate_parking_path(const ParkingTrial& trial);

// The car drawn at time t (seconds) of the path: position and heading interpolated linearly between the two
// samples around t (heading along the shorter arc), steering of the later sample; clamped to the ends.
CarPose car_pose_at(const ParkingPath& path, double t);
CarPose car_pose_of(const VehicleState& vehicle, double steering);
// Interpolates between two simulation states (alpha in [0, 1]) for drawing between fixed steps.
CarPose interpolate_car_pose(const VehicleState& previous, const VehicleState& current, double steering, double alpha);

// Sample positions as float world points (for polylines).
std::vector<Vec2f> path_points(const ParkingPath& path);

}  // namespace sc
