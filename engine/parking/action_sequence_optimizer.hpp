#pragma once
// Gauss-Newton / Levenberg-Marquardt over a fixed-length 5 Hz action sequence with box constraints
// (projected steps, bound-active variables frozen). The cost is a sum of squared residuals:
//  - goal: lateral offset, depth outside the "whole car inside the spot" band, heading (cos, sin);
//  - arrival speed (a careful driver arrives slowly);
//  - action changes between consecutive steps (no chattering between full left and full right) and a
//    small effort term;
//  - clearance to parked cars and walls, checked at every 1/15 s sub-step (parked variant).
#include <vector>

#include <Eigen/Core>

#include "engine/parking/clearance_penalty.hpp"
#include "engine/parking/differentiable_rollout.hpp"
#include "engine/parking/parking_scenario.hpp"

namespace sc {

struct PlanningCostWeights {
  double lateral_scale = 0.25;       // m of sideways offset from the spot axis per unit residual
  double depth_free = 1.5;           // m either side of the spot centre at no cost: the car is fully inside
  double depth_scale = 1.0;          // m beyond that band per unit residual
  double heading_scale = 0.04;       // (cos, sin) difference per unit residual (~2.3 degrees)
  double arrival_speed_scale = 2.0;  // m/s of final speed per unit residual
  double steering_change = 3.0;      // weight of |u1(t) - u1(t-1)|
  double throttle_change = 0.3;      // weight of |u0(t) - u0(t-1)|
  double effort = 0.05;              // weight of |u|
  double clearance = 40.0;           // per metre of disc penetration into the safety margin
  double clearance_margin = 0.15;    // m of extra clearance around the conservative disc cover
};

struct OptimizedSequence {
  Eigen::VectorXd actions;  // 2T entries in [-1, 1]
  double cost = 0.0;
  int iterations = 0;
};

class ActionSequenceOptimizer {
 public:
  ActionSequenceOptimizer(const ParkingScenario& scenario, const ParkingLayout& layout,
                          const PlanningCostWeights& weights);

  // Aims at another pose than the scenario's goal (e.g. a staging pose in front of the spot), arriving
  // with `arrival_speed` (m/s, signed: negative = reversing).
  void set_target(const Pose& target, double depth_free, double arrival_speed, double arrival_speed_scale);
  OptimizedSequence optimize(const Eigen::VectorXd& initial, int max_iterations);
  double cost(const Eigen::VectorXd& actions);

 private:
  // Fills residuals_ (and jacobian_ when `derivatives`) of the goal, arrival and clearance terms for
  // `actions`; returns the whole cost including the quadratic action-change and effort terms.
  double evaluate(const Eigen::VectorXd& actions, bool derivatives);
  void prepare_regularisation(int n);
  double regularisation_cost(const Eigen::VectorXd& z) const;

  PlanningCostWeights weights_;
  VehicleState start_;
  Pose goal_;
  double depth_free_;
  double arrival_speed_ = 0.0;
  double arrival_speed_scale_;
  ClearancePenalty clearance_;
  DifferentiableRollout rollout_;
  Eigen::VectorXd residuals_;
  Eigen::MatrixXd jacobian_;
  Eigen::MatrixXd regularisation_;           // R of the quadratic terms z' R z, rebuilt when T changes
  std::vector<ClearanceViolation> scratch_;  // clearance violations of the last evaluation
  std::vector<int> substep_of_;              // the sub-step of each violation
};

}  // namespace sc
