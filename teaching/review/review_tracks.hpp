#pragma once
// A trial as the review draws and plays it back: where the car (or pen) is before each control step, its
// heading (parking) and the input of each step (what the on-screen stick shows), in the task's world units
// (parking: metres in the lot; writing: canvas pixels, y down). Points are indexed like the
// SkillExtractor's steps, so a segment [begin, end) is the polyline points[begin..end].
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/core/task_kind.hpp"
#include "engine/parking/vehicle_model.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc::review {

struct TrackPoint {
  double x = 0.0;
  double y = 0.0;
};

struct TrialTrack {
  std::vector<TrackPoint> points;             // T + 1: before each of the T steps, then where it ended
  std::vector<double> headings;               // parking: radians at each point; writing: empty
  std::vector<std::array<double, 2>> inputs;  // T: parking (steering, throttle) in [-1, 1]; writing (dx, dy)
  double step_seconds = 0.0;                  // time one step takes when played back at 1x
  int steps() const { return static_cast<int>(inputs.size()); }
};

// `steps` is kit.steps_of(doc) (the extractor's view of the same trial).
// Parking: `end` is the car after the last step (from replaying the trial); without it the end point is
// extrapolated from the last velocity.
TrialTrack track_of(TaskKind task, const StepSequence& steps, const std::optional<VehicleState>& end);

// The track of a projected drill's ghost path (PlayableDrill::ghost_path, one point per state).
TrialTrack ghost_track(TaskKind task, const std::vector<std::array<double, 2>>& ghost_path, const StepSequence& steps);

}  // namespace sc::review
