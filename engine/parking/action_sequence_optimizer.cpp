#include "engine/parking/action_sequence_optimizer.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace sc {

ActionSequenceOptimizer::ActionSequenceOptimizer(const ParkingScenario& scenario, const ParkingLayout& layout,
                                                 const PlanningCostWeights& weights)
    : weights_(weights),
      start_(initial_vehicle_state(scenario)),
      goal_(goal_pose(scenario)),
      depth_free_(weights.depth_free),
      arrival_speed_scale_(weights.arrival_speed_scale),
      clearance_(layout, weights.clearance_margin) {}

void ActionSequenceOptimizer::set_target(const Pose& target, double depth_free, double arrival_speed,
                                         double arrival_speed_scale) {
  goal_ = target;
  depth_free_ = depth_free;
  arrival_speed_ = arrival_speed;
  arrival_speed_scale_ = arrival_speed_scale;
}

void ActionSequenceOptimizer::prepare_regularisation(int n) {
  if (regularisation_.rows() == n) return;
  // Action-change and effort terms are quadratic in z: cost z' R z with a constant banded R.
  const auto& w = weights_;
  regularisation_.setZero(n, n);
  for (int i = 0; i < n; ++i) regularisation_(i, i) = w.effort * w.effort;
  for (int t = 1; t < n / 2; ++t) {
    for (int c = 0; c < 2; ++c) {
      const double w2 = std::pow(c == 0 ? w.throttle_change : w.steering_change, 2);
      const int a = 2 * t + c, b = 2 * (t - 1) + c;
      regularisation_(a, a) += w2;
      regularisation_(b, b) += w2;
      regularisation_(a, b) -= w2;
      regularisation_(b, a) -= w2;
    }
  }
}

double ActionSequenceOptimizer::regularisation_cost(const Eigen::VectorXd& z) const {
  // z' R z without the dense product.
  const auto& w = weights_;
  double sum = w.effort * w.effort * z.squaredNorm();
  const double wt = w.throttle_change * w.throttle_change, ws = w.steering_change * w.steering_change;
  for (Eigen::Index i = 2; i + 1 < z.size(); i += 2)
    sum += wt * std::pow(z[i] - z[i - 2], 2) + ws * std::pow(z[i + 1] - z[i - 1], 2);
  return sum;
}

double ActionSequenceOptimizer::evaluate(const Eigen::VectorXd& z, bool derivatives) {
  const auto& w = weights_;
  const int n = static_cast<int>(z.size());
  prepare_regularisation(n);
  rollout_.run(start_, z, derivatives);

  scratch_.clear();
  substep_of_.clear();
  if (!clearance_.empty()) {
    for (int k = 1; k <= rollout_.substeps(); ++k) {
      const std::size_t before = scratch_.size();
      clearance_.violations(rollout_.state(k), scratch_);
      substep_of_.insert(substep_of_.end(), scratch_.size() - before, k);
    }
  }
  const int m = 5 + static_cast<int>(scratch_.size());
  residuals_.resize(m);
  if (derivatives) jacobian_.setZero(m, n);

  const VehicleState& end = rollout_.state(rollout_.substeps());
  const auto& s_end = rollout_.sensitivity(rollout_.substeps());
  const double ch = std::cos(goal_.heading), sh = std::sin(goal_.heading);
  const double dx = end.x - goal_.x, dy = end.y - goal_.y;
  const double lateral = -sh * dx + ch * dy;
  const double along = ch * dx + sh * dy;
  const double excess = std::max(std::fabs(along) - depth_free_, 0.0);
  const double cos_h = std::cos(end.heading), sin_h = std::sin(end.heading);
  residuals_[0] = lateral / w.lateral_scale;
  residuals_[1] = excess / w.depth_scale;
  residuals_[2] = (cos_h - ch) / w.heading_scale;
  residuals_[3] = (sin_h - sh) / w.heading_scale;
  residuals_[4] = (end.speed - arrival_speed_) / arrival_speed_scale_;
  if (derivatives) {
    jacobian_.row(0) = (-sh * s_end.row(0) + ch * s_end.row(1)) / w.lateral_scale;
    if (excess > 0)
      jacobian_.row(1) = (along > 0 ? 1.0 : -1.0) * (ch * s_end.row(0) + sh * s_end.row(1)) / w.depth_scale;
    jacobian_.row(2) = -sin_h * s_end.row(2) / w.heading_scale;
    jacobian_.row(3) = cos_h * s_end.row(2) / w.heading_scale;
    jacobian_.row(4) = s_end.row(3) / arrival_speed_scale_;
  }
  for (std::size_t v = 0; v < scratch_.size(); ++v) {
    const auto& hit = scratch_[v];
    const int row = 5 + static_cast<int>(v);
    residuals_[row] = w.clearance * hit.depth;
    if (derivatives) {
      const auto& s = rollout_.sensitivity(substep_of_[v]);
      jacobian_.row(row) =
          w.clearance * (hit.d_pose[0] * s.row(0) + hit.d_pose[1] * s.row(1) + hit.d_pose[2] * s.row(2));
    }
  }
  return residuals_.squaredNorm() + regularisation_cost(z);
}

double ActionSequenceOptimizer::cost(const Eigen::VectorXd& actions) { return evaluate(actions, false); }

OptimizedSequence ActionSequenceOptimizer::optimize(const Eigen::VectorXd& initial, int max_iterations) {
  const int n = static_cast<int>(initial.size());
  Eigen::VectorXd z = initial.cwiseMax(-1.0).cwiseMin(1.0);
  double current = evaluate(z, true);
  double lambda = 1e-3;
  int iteration = 0;
  Eigen::MatrixXd h(n, n), damped(n, n);
  Eigen::VectorXd g(n), step(n), candidate(n);
  Eigen::LLT<Eigen::MatrixXd> solver(n);  // the damped matrix is positive definite
  for (; iteration < max_iterations; ++iteration) {
    g.noalias() = jacobian_.transpose() * residuals_;
    g.noalias() += regularisation_ * z;
    h = regularisation_;
    h.selfadjointView<Eigen::Lower>().rankUpdate(jacobian_.transpose());
    h.triangularView<Eigen::StrictlyUpper>() = h.transpose();
    // Variables at a bound whose gradient pushes them outwards stay fixed this iteration.
    for (int i = 0; i < n; ++i) {
      const bool stuck = (z[i] >= 1.0 && g[i] < 0.0) || (z[i] <= -1.0 && g[i] > 0.0);
      if (stuck) {
        h.row(i).setZero();
        h.col(i).setZero();
        h(i, i) = 1.0;
        g[i] = 0.0;
      }
    }
    bool improved = false;
    while (lambda < 1e8) {
      damped = h;
      damped.diagonal() += lambda * (h.diagonal().array() + 1e-6).matrix();
      step = solver.compute(damped).solve(-g);
      candidate = (z + step).cwiseMax(-1.0).cwiseMin(1.0);
      const double trial = evaluate(candidate, false);
      if (trial < current) {
        const double gain = current - trial;
        z = candidate;
        current = evaluate(z, true);
        lambda = std::max(lambda / 3.0, 1e-7);
        improved = gain > 1e-7 * (1.0 + current);
        break;
      }
      lambda *= 5.0;
    }
    if (!improved) break;
  }
  return {z, current, iteration};
}

}  // namespace sc
