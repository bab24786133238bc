#include "teaching/tasks/parking_idle_start.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// The car's speed in the observation before step t (velocity scaled by 1/5, reference-facts §1.6).
double speed_before(const StepSequence& steps, int t) {
  const auto at = static_cast<std::size_t>(t) * static_cast<std::size_t>(steps.state_dim);
  return 5.0 * std::hypot(steps.states[at + 2], steps.states[at + 3]);
}

StepSequence from_step(const StepSequence& steps, int k) {
  StepSequence out;
  out.state_dim = steps.state_dim;
  out.action_dim = steps.action_dim;
  out.states.assign(steps.states.begin() + static_cast<std::ptrdiff_t>(k) * steps.state_dim, steps.states.end());
  out.actions.assign(steps.actions.begin() + static_cast<std::ptrdiff_t>(k) * steps.action_dim, steps.actions.end());
  return out;
}

Segmentation moved_back(Segmentation s, int k) {
  for (SkillSegment& seg : s.segments) {
    seg.begin += k;
    seg.end += k;
  }
  if (!s.segments.empty()) s.segments.front().begin = 0;
  return s;
}

}  // namespace

int idle_start_steps(const StepSequence& steps) {
  if (steps.state_dim != kParkingStateDim) return 0;
  const int length = steps.length();
  if (static_cast<int>(steps.states.size()) < length * kParkingStateDim) return 0;
  int k = 0;
  // The speed after step k is the speed before step k + 1.
  while (k + 1 < length && speed_before(steps, k + 1) < kIdleStartSpeed) ++k;
  return k;
}

ParkingIdleStartExtractor::ParkingIdleStartExtractor(std::shared_ptr<const SkillExtractor> inner)
    : inner_(std::move(inner)) {
  if (!inner_) throw InputError("parking skill extractor", "no extractor to wrap");
}

Segmentation ParkingIdleStartExtractor::extract(const StepSequence& trajectory) const {
  const int k = idle_start_steps(trajectory);
  return k == 0 ? inner_->extract(trajectory) : moved_back(inner_->extract(from_step(trajectory, k)), k);
}

std::vector<Segmentation> ParkingIdleStartExtractor::extract_all(const std::vector<StepSequence>& trajectories) const {
  std::vector<int> idle;
  std::vector<StepSequence> moving;
  idle.reserve(trajectories.size());
  moving.reserve(trajectories.size());
  for (const StepSequence& t : trajectories) {
    idle.push_back(idle_start_steps(t));
    moving.push_back(idle.back() == 0 ? t : from_step(t, idle.back()));
  }
  std::vector<Segmentation> out = inner_->extract_all(moving);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (idle[i] > 0) out[i] = moved_back(std::move(out[i]), idle[i]);
  return out;
}

}  // namespace sc
