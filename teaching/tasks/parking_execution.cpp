#include "teaching/tasks/parking_execution.hpp"

#include <cmath>

#include "engine/parking/parking_sim.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

struct Pose2 {
  double x = 0.0, y = 0.0, heading = 0.0;
};

Pose2 pose_at(const StepSequence& steps, int t) {
  const std::size_t o = static_cast<std::size_t>(t) * kParkingStateDim;
  return {100.0 * steps.states[o], 100.0 * steps.states[o + 1], std::atan2(steps.states[o + 5], steps.states[o + 4])};
}

// Pose b seen from pose a: displacement along and across a's heading, heading change.
Pose2 relative(const Pose2& a, const Pose2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, c = std::cos(a.heading), s = std::sin(a.heading);
  return {c * dx + s * dy, -s * dx + c * dy, b.heading - a.heading};
}

}  // namespace

std::vector<TracePoint3> parking_trace_points(const StepSequence& steps) {
  std::vector<TracePoint3> out;
  for (int t = 0; t < steps.length(); ++t) {
    const std::size_t o = static_cast<std::size_t>(t) * kParkingStateDim;
    ParkingObservation obs{};
    for (int k = 0; k < kParkingStateDim; ++k)
      obs[static_cast<std::size_t>(k)] = steps.states[o + static_cast<std::size_t>(k)];
    const VehicleState v = vehicle_from_observation(obs);
    out.push_back({v.x, v.y, v.speed});
  }
  return out;
}

double parking_execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                int begin, int end) {
  const auto& w = parking::kRewardWeights;
  int learner_start = -1;
  double sum = 0.0;
  int pairs = 0;
  for (const auto& [e, l] : path) {
    if (e < begin || e >= end || e >= expert.length() || l >= learner.length()) continue;
    if (learner_start < 0) learner_start = l;
    const Pose2 a = relative(pose_at(expert, begin), pose_at(expert, e));
    const Pose2 b = relative(pose_at(learner, learner_start), pose_at(learner, l));
    const double d = w[0] * std::abs(a.x - b.x) / 100.0 + w[1] * std::abs(a.y - b.y) / 100.0 +
                     w[4] * std::abs(std::cos(a.heading) - std::cos(b.heading)) +
                     w[5] * std::abs(std::sin(a.heading) - std::sin(b.heading));
    sum -= std::sqrt(d);
    ++pairs;
  }
  return pairs > 0 ? sum / pairs : 0.0;
}

}  // namespace sc
