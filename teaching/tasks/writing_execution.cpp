#include "teaching/tasks/writing_execution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/writing/writing_score.hpp"

namespace sc {
namespace {

double credit(double d) {
  const writing::WritingScoreParams p;
  if (d <= p.tolerance_px) return 1.0;
  if (d >= p.cutoff_px) return 0.0;
  return (p.cutoff_px - d) / (p.cutoff_px - p.tolerance_px);
}

// Mean credit of each point of `from` at its distance to the nearest point of `to`.
double mean_credit(const std::vector<TracePoint3>& from, const std::vector<TracePoint3>& to) {
  if (from.empty() || to.empty()) return 0.0;
  double sum = 0.0;
  for (const TracePoint3& a : from) {
    double nearest = std::numeric_limits<double>::infinity();  // squared: one square root per point
    for (const TracePoint3& b : to)
      nearest = std::min(nearest, (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]));
    sum += credit(std::sqrt(nearest));
  }
  return sum / static_cast<double>(from.size());
}

}  // namespace

std::vector<TracePoint3> writing_trace_points(const StepSequence& steps) {
  std::vector<TracePoint3> out;
  for (int t = 0; t < steps.length(); ++t) {
    const std::size_t o = static_cast<std::size_t>(t) * static_cast<std::size_t>(steps.state_dim);
    out.push_back({steps.states[o], steps.states[o + 1], 0.0});
  }
  return out;
}

double writing_execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                int begin, int end) {
  const std::vector<TracePoint3> e = writing_trace_points(expert), l = writing_trace_points(learner);
  std::vector<TracePoint3> expert_part, learner_part;
  for (int t = std::max(begin, 0); t < end && t < static_cast<int>(e.size()); ++t)
    expert_part.push_back(e[static_cast<std::size_t>(t)]);
  // The learner's part is moved by the mean offset of its aligned pairs: the segment's shape is compared,
  // not where earlier letters left the pen.
  double dx = 0.0, dy = 0.0;
  int pairs = 0, last = -1;
  for (const auto& [i, j] : path) {
    if (i < begin || i >= end || i >= static_cast<int>(e.size()) || j >= static_cast<int>(l.size())) continue;
    dx += l[static_cast<std::size_t>(j)][0] - e[static_cast<std::size_t>(i)][0];
    dy += l[static_cast<std::size_t>(j)][1] - e[static_cast<std::size_t>(i)][1];
    ++pairs;
    if (j == last) continue;
    learner_part.push_back(l[static_cast<std::size_t>(j)]);
    last = j;
  }
  if (expert_part.empty()) return 0.0;
  for (TracePoint3& p : learner_part) {
    p[0] -= dx / std::max(pairs, 1);
    p[1] -= dy / std::max(pairs, 1);
  }
  return mean_credit(expert_part, learner_part) * mean_credit(learner_part, expert_part) - 1.0;
}

}  // namespace sc
