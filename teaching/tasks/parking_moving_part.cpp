#include "teaching/tasks/parking_moving_part.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "teaching/skills/step_range.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

bool is_parking(const StepSequence& steps) {
  return steps.state_dim == kParkingStateDim &&
         steps.states.size() >= static_cast<std::size_t>(steps.length()) * kParkingStateDim;
}

// The car's speed in the observation before step t (velocity scaled by 1/5, reference-facts §1.6).
double speed_before(const StepSequence& steps, int t) {
  const auto at = static_cast<std::size_t>(t) * static_cast<std::size_t>(steps.state_dim);
  return 5.0 * std::hypot(steps.states[at + 2], steps.states[at + 3]);
}

struct MovingPart {
  int begin = 0, end = 0;  // [begin, end) of the drive's steps
};

MovingPart moving_part(const StepSequence& steps) {
  const int length = steps.length();
  const int start = standing_start_steps(steps);
  const int end = std::max(start + 1, length - standing_end_steps(steps));
  return {start, std::min(end, length)};
}

Segmentation stretched(Segmentation s, MovingPart part, int length) {
  s = shifted(std::move(s), part.begin);
  if (!s.segments.empty()) {
    s.segments.front().begin = 0;
    s.segments.back().end = length;
  }
  return s;
}

bool whole(MovingPart part, int length) { return part.begin == 0 && part.end == length; }

}  // namespace

int standing_start_steps(const StepSequence& steps) {
  if (!is_parking(steps)) return 0;
  const int length = steps.length();
  int k = 0;
  // The speed after step k is the speed before step k + 1.
  while (k + 1 < length && speed_before(steps, k + 1) < kStandingSpeed) ++k;
  return k;
}

int moving_part_length(const StepSequence& steps) {
  const MovingPart part = moving_part(steps);
  return part.end - part.begin;
}

int standing_end_steps(const StepSequence& steps) {
  if (!is_parking(steps)) return 0;
  const int length = steps.length();
  int e = 0;
  for (int t = length - 1; t > 0; --t, ++e) {
    const double after = t + 1 < length ? speed_before(steps, t + 1) : speed_before(steps, t);
    if (speed_before(steps, t) >= kStandingSpeed || after >= kStandingSpeed) break;
  }
  return e;
}

ParkingMovingPartExtractor::ParkingMovingPartExtractor(std::shared_ptr<const SkillExtractor> inner)
    : inner_(std::move(inner)) {
  if (!inner_) throw InputError("parking skill extractor", "no extractor to wrap");
}

Segmentation ParkingMovingPartExtractor::extract(const StepSequence& trajectory) const {
  const MovingPart part = moving_part(trajectory);
  const int length = trajectory.length();
  if (length == 0 || whole(part, length)) return inner_->extract(trajectory);
  return stretched(inner_->extract(steps_between(trajectory, part.begin, part.end)), part, length);
}

std::vector<Segmentation> ParkingMovingPartExtractor::extract_all(const std::vector<StepSequence>& trajectories) const {
  std::vector<MovingPart> parts;
  std::vector<StepSequence> moving;
  parts.reserve(trajectories.size());
  moving.reserve(trajectories.size());
  for (const StepSequence& t : trajectories) {
    parts.push_back(moving_part(t));
    moving.push_back(t.length() == 0 || whole(parts.back(), t.length())
                         ? t
                         : steps_between(t, parts.back().begin, parts.back().end));
  }
  std::vector<Segmentation> out = inner_->extract_all(moving);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int length = trajectories[i].length();
    if (length > 0 && !whole(parts[i], length)) out[i] = stretched(std::move(out[i]), parts[i], length);
  }
  return out;
}

}  // namespace sc
