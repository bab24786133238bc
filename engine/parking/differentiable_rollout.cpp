#include "engine/parking/differentiable_rollout.hpp"

#include <cmath>

namespace sc {

void DifferentiableRollout::run(const VehicleState& start, const Eigen::VectorXd& actions, bool derivatives) {
  using namespace parking;
  steps_ = static_cast<int>(actions.size() / 2);
  const int n = 2 * steps_;
  const int count = 3 * steps_ + 1;
  states_.resize(count);
  states_[0] = start;
  if (derivatives && (sensitivities_.size() != static_cast<std::size_t>(count) || sensitivities_[0].cols() != n)) {
    // Columns of actions after sub-step k are never written, so they stay zero across runs of equal length.
    sensitivities_.assign(count, Eigen::Matrix<double, 4, Eigen::Dynamic>::Zero(4, n));
  }
  for (int t = 0; t < steps_; ++t) {
    const double u0 = actions[2 * t];
    const double u1 = actions[2 * t + 1];
    const double delta = kMaxSteering * u1;
    const double tan_d = std::tan(delta);
    const double beta = std::atan(0.5 * tan_d);
    // d beta / d u1 = (pi/4) * 0.5 sec^2(delta) / (1 + 0.25 tan^2(delta))
    const double dbeta_du1 = kMaxSteering * 0.5 * (1.0 + tan_d * tan_d) / (1.0 + 0.25 * tan_d * tan_d);
    const double sin_b = std::sin(beta);
    const double cos_b = std::cos(beta);
    for (int j = 0; j < 3; ++j) {
      const int k = 3 * t + j;
      const VehicleState& s = states_[k];
      const double c = std::cos(s.heading + beta);
      const double sn = std::sin(s.heading + beta);
      VehicleState& next = states_[k + 1];
      next.x = s.x + s.speed * c * kDt;
      next.y = s.y + s.speed * sn * kDt;
      next.heading = s.heading + s.speed * sin_b / kHalfLength * kDt;
      next.speed = s.speed + kMaxAcceleration * u0 * kDt;
      if (!derivatives) continue;
      // The sub-step Jacobian is identity plus four entries; apply it column by column (only actions
      // 0..t can have influenced the state).
      const double a02 = -s.speed * sn * kDt, a03 = c * kDt;
      const double a12 = s.speed * c * kDt, a13 = sn * kDt;
      const double a23 = sin_b / kHalfLength * kDt;
      const auto& in = sensitivities_[k];
      auto& out = sensitivities_[k + 1];
      const int used = 2 * (t + 1);
      for (int col = 0; col < used; ++col) {
        const double heading = in(2, col), speed = in(3, col);
        out(0, col) = in(0, col) + a02 * heading + a03 * speed;
        out(1, col) = in(1, col) + a12 * heading + a13 * speed;
        out(2, col) = heading + a23 * speed;
        out(3, col) = speed;
      }
      out(3, 2 * t) += kMaxAcceleration * kDt;
      out(0, 2 * t + 1) += -s.speed * sn * kDt * dbeta_du1;
      out(1, 2 * t + 1) += s.speed * c * kDt * dbeta_du1;
      out(2, 2 * t + 1) += s.speed * cos_b / kHalfLength * kDt * dbeta_du1;
    }
  }
}

}  // namespace sc
