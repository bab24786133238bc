#include "teaching/review/review_tracks.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/parking/parking_sim.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::review {
namespace {

float at(const std::vector<float>& v, int row, int dim, int col) {
  return v[static_cast<std::size_t>(row) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(col)];
}

void fill_inputs(TrialTrack& track, const StepSequence& steps) {
  for (int t = 0; t < steps.length(); ++t)
    track.inputs.push_back({at(steps.actions, t, steps.action_dim, 0),
                            steps.action_dim > 1 ? at(steps.actions, t, steps.action_dim, 1) : 0.0});
}

}  // namespace

TrialTrack track_of(TaskKind task, const StepSequence& steps, const std::optional<VehicleState>& end) {
  TrialTrack track;
  fill_inputs(track, steps);
  const int T = steps.length();
  if (T == 0 || steps.state_dim < 2) return track;
  if (task == TaskKind::parking) {
    // Observation layout (reference-facts §1.6): x/100, y/100, vx/5, vy/5, cos h, sin h, goal ...
    for (int t = 0; t < T; ++t) {
      track.points.push_back(
          {at(steps.states, t, steps.state_dim, 0) * 100.0, at(steps.states, t, steps.state_dim, 1) * 100.0});
      track.headings.push_back(
          std::atan2(at(steps.states, t, steps.state_dim, 5), at(steps.states, t, steps.state_dim, 4)));
    }
    track.step_seconds = 1.0 / parking::kControlHz;
    if (end) {
      track.points.push_back({end->x, end->y});
      track.headings.push_back(end->heading);
    } else {
      // Only the states before each action are known (a drill's steps): the end is one control step at the
      // last velocity away, close enough to draw the line to it.
      const double vx = at(steps.states, T - 1, steps.state_dim, 2) * 5.0,
                   vy = at(steps.states, T - 1, steps.state_dim, 3) * 5.0;
      track.points.push_back(
          {track.points.back().x + vx * track.step_seconds, track.points.back().y + vy * track.step_seconds});
      track.headings.push_back(track.headings.back());
    }
  } else {
    for (int t = 0; t < T; ++t)
      track.points.push_back({at(steps.states, t, steps.state_dim, 0), at(steps.states, t, steps.state_dim, 1)});
    track.points.push_back(
        {track.points.back().x + track.inputs.back()[0], track.points.back().y + track.inputs.back()[1]});
    track.step_seconds = 1.0 / writing::kExpertStepsPerSecond;
  }
  return track;
}

TrialTrack ghost_track(TaskKind task, const std::vector<std::array<double, 2>>& ghost_path, const StepSequence& steps) {
  TrialTrack track = track_of(task, steps, std::nullopt);
  // The projector's ghost path is exact (it includes the final state): prefer it to the approximated end.
  if (ghost_path.size() == static_cast<std::size_t>(steps.length()) + 1) {
    track.points.clear();
    for (const auto& p : ghost_path) track.points.push_back({p[0], p[1]});
    if (!track.headings.empty()) track.headings.push_back(track.headings.back());
    if (track.headings.size() > track.points.size()) track.headings.resize(track.points.size());
  }
  return track;
}

}  // namespace sc::review
