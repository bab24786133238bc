#include "teaching/students/writing_pen_policy.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "engine/writing/writing_score.hpp"

namespace sc {
namespace {

constexpr int kStateDim = writing::kWritingStateDim;
constexpr int kActionDim = 2;
constexpr double kTimerScale = 1000.0;  // steps; classic words have 1250-2700

void scale_state(const float* raw, float* out) {
  out[0] = static_cast<float>(raw[0] / (writing::kCanvasWidth / 2.0) - 1.0);
  out[1] = static_cast<float>((raw[1] - writing::kStartY) / 50.0);  // words stay within y 66-184
  out[2] = static_cast<float>(raw[2] / kTimerScale);
  for (int g = 3; g < kStateDim; ++g) out[g] = static_cast<float>((raw[g] - 2.5) / 3.5);  // ids -1..6
}

}  // namespace

std::vector<float> pen_features(const float* raw_state) {
  std::vector<float> out(kStateDim);
  scale_state(raw_state, out.data());
  return out;
}

BcDataset pen_dataset(const BcDataset& raw) {
  if (raw.size() > 0 && (raw.state_dim != kStateDim || raw.action_dim != kActionDim))
    throw InputError("writing pen data", "expected 13-D states and 2-D steps (classic alphabet), got " +
                                             std::to_string(raw.state_dim) + "-D and " +
                                             std::to_string(raw.action_dim) + "-D");
  BcDataset out;
  out.state_dim = kStateDim;
  out.action_dim = kActionDim;
  out.states.resize(raw.states.size());
  for (int i = 0; i < raw.size(); ++i)
    scale_state(raw.states.data() + static_cast<std::size_t>(i) * kStateDim,
                out.states.data() + static_cast<std::size_t>(i) * kStateDim);
  out.actions.reserve(raw.actions.size());
  for (float a : raw.actions) out.actions.push_back(static_cast<float>(a / kPenActionScale));
  return out;
}

std::vector<writing::TracePoint> rollout_pen(const BcPolicy& policy, const writing::WordTrajectory& gold) {
  std::vector<float> state(kStateDim);
  for (int g = 0; g < writing::kMaxWordSymbols; ++g)
    state[static_cast<std::size_t>(3 + g)] = static_cast<float>(gold.goal[static_cast<std::size_t>(g)]);
  writing::TracePoint pen{gold.start.x, gold.start.y, true};
  std::vector<writing::TracePoint> trace{pen};
  trace.reserve(gold.steps.size() + 1);
  for (std::size_t t = 0; t < gold.steps.size(); ++t) {
    state[0] = static_cast<float>(pen.x);
    state[1] = static_cast<float>(pen.y);
    state[2] = static_cast<float>(t);
    const std::vector<float> step = policy.act(pen_features(state.data()));
    // The canvas bounds a real pen; keeping the student on it also keeps its trial file valid.
    pen.x = std::clamp(pen.x + kPenActionScale * step[0], 0.0, writing::kCanvasWidth);
    pen.y = std::clamp(pen.y + kPenActionScale * step[1], 0.0, writing::kCanvasHeight);
    trace.push_back(pen);
  }
  return trace;
}

double pen_trace_reward(const writing::WordTrajectory& gold, const std::vector<writing::TracePoint>& trace) {
  return std::min(writing::score_writing(gold.points(), trace).score, 0.0);
}

double score_pen_student(const BcPolicy& policy, const std::vector<writing::WordTrajectory>& words) {
  if (words.empty()) return 0.0;
  double total = 0.0;
  for (const writing::WordTrajectory& w : words) total += pen_trace_reward(w, rollout_pen(policy, w));
  return total / static_cast<double>(words.size());
}

}  // namespace sc
