#pragma once
// The bicycle model rolled out over a 5 Hz action sequence together with the exact derivatives of every
// sub-step state with respect to every action (forward sensitivities), for the expert's Gauss-Newton
// optimiser. Same update as bicycle_substep() without the speed guard, which never acts below 40 m/s
// (the planner's final trajectory is always re-checked in ParkingSim).
#include <vector>

#include <Eigen/Core>

#include "engine/parking/vehicle_model.hpp"

namespace sc {

// Actions as a vector z = [u0_0, u1_0, u0_1, u1_1, ...] (2T entries), assumed already within [-1, 1].
class DifferentiableRollout {
 public:
  // Runs the model from `start`; with `derivatives` false only the states are computed.
  void run(const VehicleState& start, const Eigen::VectorXd& actions, bool derivatives);

  int control_steps() const { return steps_; }
  int substeps() const { return 3 * steps_; }
  // State after sub-step k (k = 0 is the start, k = 3t is the end of control step t).
  const VehicleState& state(int k) const { return states_[k]; }
  // d state(k) / d actions: rows x, y, heading, speed; 2T columns (zero for actions after step k/3).
  const Eigen::Matrix<double, 4, Eigen::Dynamic>& sensitivity(int k) const { return sensitivities_[k]; }

 private:
  int steps_ = 0;
  std::vector<VehicleState> states_;
  std::vector<Eigen::Matrix<double, 4, Eigen::Dynamic>> sensitivities_;
};

}  // namespace sc
