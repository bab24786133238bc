#include "engine/writing/step_data.hpp"

namespace sc::writing {
namespace {

void push_state(WritingStepData& data, double x, double y, int timer, const std::vector<int>& goal) {
  data.states.push_back(static_cast<float>(x));
  data.states.push_back(static_cast<float>(y));
  data.states.push_back(static_cast<float>(timer));
  for (int g : goal) data.states.push_back(static_cast<float>(g));
}

void push_action(WritingStepData& data, double dx, double dy, bool pen) {
  data.actions.push_back(static_cast<float>(dx));
  data.actions.push_back(static_cast<float>(dy));
  if (data.action_dim == 3) data.actions.push_back(pen ? 1.0f : 0.0f);
}

}  // namespace

int writing_action_dim(AlphabetKind kind) { return kind == AlphabetKind::Classic ? 2 : 3; }

WritingStepData expert_step_data(const WordTrajectory& word) {
  WritingStepData data;
  data.action_dim = writing_action_dim(word.alphabet);
  data.character_starts = word.character_starts;
  const auto pts = word.points();
  for (std::size_t t = 0; t < word.steps.size(); ++t) {
    push_state(data, pts[t].x, pts[t].y, static_cast<int>(t), word.goal);
    push_action(data, word.steps[t].dx, word.steps[t].dy, word.steps[t].pen);
  }
  return data;
}

WritingStepData trace_step_data(const std::vector<TracePoint>& points, AlphabetKind kind, std::string_view word) {
  WritingStepData data;
  data.action_dim = writing_action_dim(kind);
  const auto goal = goal_vector(kind, word);
  for (std::size_t t = 0; t + 1 < points.size(); ++t) {
    push_state(data, points[t].x, points[t].y, static_cast<int>(t), goal);
    push_action(data, points[t + 1].x - points[t].x, points[t + 1].y - points[t].y, points[t + 1].pen);
  }
  return data;
}

}  // namespace sc::writing
