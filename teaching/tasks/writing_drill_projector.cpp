#include "teaching/tasks/writing_drill_projector.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace sc {
namespace {

// Shift that moves [lo, hi] inside [0, size]; a span longer than the canvas keeps its low edge at 0.
double inside_shift(double lo, double hi, double size) {
  if (lo < 0.0) return -lo;
  if (hi > size) return std::max(size - hi, -lo);
  return 0.0;
}

bool pen_down(const StepSequence& s, int t) {
  return s.action_dim < 3 || s.actions[static_cast<std::size_t>(t * s.action_dim + 2)] > 0.5f;
}

}  // namespace

WritingDrillProjector::WritingDrillProjector(std::vector<StepSequence> experts) : experts_(std::move(experts)) {
  for (std::size_t i = 0; i < experts_.size(); ++i)
    if (experts_[i].state_dim < 2 || experts_[i].action_dim < 2)
      throw InputError("writing drill projector", "expert " + std::to_string(i) + " has no pen position/moves");
}

PlayableDrill WritingDrillProjector::project(const DrillPlan& plan) const {
  // Validates indices and intervals, and gives the expert states/actions end to end.
  StepSequence steps = concatenate_expert_steps(plan, experts_);
  const int sd = steps.state_dim;
  const int ad = steps.action_dim;
  const int total = steps.length();

  // Chain the moves from the first segment's original start.
  std::vector<std::array<double, 2>> path;
  path.reserve(static_cast<std::size_t>(total) + 1);
  double x = steps.states[0];
  double y = steps.states[1];
  path.push_back({x, y});
  for (int t = 0; t < total; ++t) {
    x += steps.actions[static_cast<std::size_t>(t * ad)];
    y += steps.actions[static_cast<std::size_t>(t * ad + 1)];
    path.push_back({x, y});
  }
  double min_x = path[0][0], max_x = min_x, min_y = path[0][1], max_y = min_y;
  for (const auto& p : path) {
    min_x = std::min(min_x, p[0]);
    max_x = std::max(max_x, p[0]);
    min_y = std::min(min_y, p[1]);
    max_y = std::max(max_y, p[1]);
  }
  const double dx = inside_shift(min_x, max_x, writing::kCanvasWidth);
  const double dy = inside_shift(min_y, max_y, writing::kCanvasHeight);
  for (auto& p : path) p = {p[0] + dx, p[1] + dy};

  for (int t = 0; t < total; ++t) {
    float* state = &steps.states[static_cast<std::size_t>(t * sd)];
    state[0] = static_cast<float>(path[static_cast<std::size_t>(t)][0]);
    state[1] = static_cast<float>(path[static_cast<std::size_t>(t)][1]);
    if (sd > 2) state[2] = static_cast<float>(t);  // the drill's own clock, as a trace of it would have
  }
  PlayableDrill drill;
  drill.plan = plan;
  drill.final_state.assign(steps.states.end() - sd, steps.states.end());
  drill.final_state[0] = static_cast<float>(path.back()[0]);
  drill.final_state[1] = static_cast<float>(path.back()[1]);
  if (sd > 2) drill.final_state[2] = static_cast<float>(total);
  drill.steps = std::move(steps);
  drill.ghost_path = std::move(path);
  drill.segment_starts = plan.segment_starts();
  drill.drill_return = 0.0;
  drill.success = true;
  return drill;
}

std::vector<writing::TracePoint> WritingDrillProjector::drill_trace(const PlayableDrill& drill) {
  std::vector<writing::TracePoint> trace;
  trace.reserve(drill.ghost_path.size());
  for (std::size_t i = 0; i < drill.ghost_path.size(); ++i) {
    const bool pen = i == 0 || pen_down(drill.steps, static_cast<int>(i) - 1);
    trace.push_back({drill.ghost_path[i][0], drill.ghost_path[i][1], pen});
  }
  return trace;
}

}  // namespace sc
