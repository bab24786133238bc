#include "teaching/tasks/writing_execution.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/writing/point_grid.hpp"
#include "engine/writing/writing_score.hpp"

namespace sc {
namespace {

double credit(double d) {
  const writing::WritingScoreParams p;
  if (d <= p.tolerance_px) return 1.0;
  if (d >= p.cutoff_px) return 0.0;
  return (p.cutoff_px - d) / (p.cutoff_px - p.tolerance_px);
}

// Mean credit of each point of `from` at its distance to the nearest point of `to`. Only points within the
// cutoff earn credit, so a grid of cutoff-sized cells finds the same nearest distance without scanning all of
// `to`, and a point within the tolerance ends the search (full credit either way).
double mean_credit(const std::vector<TracePoint3>& from, const std::vector<TracePoint3>& to) {
  if (from.empty() || to.empty()) return 0.0;
  const writing::WritingScoreParams p;
  std::vector<writing::Point2> targets;
  for (const TracePoint3& b : to) targets.push_back({b[0], b[1]});
  const writing::PointGrid grid(targets, p.cutoff_px);
  double sum = 0.0;
  for (const TracePoint3& a : from) sum += credit(grid.nearest({a[0], a[1]}, p.tolerance_px));
  return sum / static_cast<double>(from.size());
}

// How the learner's aligned points are laid over the expert's: both centroids, and the ratio of the expert's
// to the learner's root-mean-square distance from them, clamped to [1 / kMaxSizeRatio, kMaxSizeRatio].
struct SizeAndPlace {
  double expert_x = 0, expert_y = 0, learner_x = 0, learner_y = 0, scale = 1;
};

SizeAndPlace fit_size_and_place(const std::vector<std::pair<TracePoint3, TracePoint3>>& pairs) {
  SizeAndPlace fit;
  if (pairs.empty()) return fit;
  for (const auto& [a, b] : pairs) {
    fit.expert_x += a[0];
    fit.expert_y += a[1];
    fit.learner_x += b[0];
    fit.learner_y += b[1];
  }
  const double n = static_cast<double>(pairs.size());
  fit.expert_x /= n;
  fit.expert_y /= n;
  fit.learner_x /= n;
  fit.learner_y /= n;
  double expert_spread = 0, learner_spread = 0;
  for (const auto& [a, b] : pairs) {
    expert_spread += (a[0] - fit.expert_x) * (a[0] - fit.expert_x) + (a[1] - fit.expert_y) * (a[1] - fit.expert_y);
    learner_spread += (b[0] - fit.learner_x) * (b[0] - fit.learner_x) + (b[1] - fit.learner_y) * (b[1] - fit.learner_y);
  }
  if (learner_spread > 1e-9)
    fit.scale = std::clamp(std::sqrt(expert_spread / learner_spread), 1.0 / kMaxSizeRatio, kMaxSizeRatio);
  return fit;
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
  std::vector<std::pair<TracePoint3, TracePoint3>> pairs;  // (expert, learner) aligned within the segment
  int last = -1;
  for (const auto& [i, j] : path) {
    if (i < begin || i >= end || i >= static_cast<int>(e.size()) || j >= static_cast<int>(l.size())) continue;
    pairs.emplace_back(e[static_cast<std::size_t>(i)], l[static_cast<std::size_t>(j)]);
    if (j == last) continue;
    learner_part.push_back(l[static_cast<std::size_t>(j)]);
    last = j;
  }
  if (expert_part.empty()) return 0.0;
  const SizeAndPlace fit = fit_size_and_place(pairs);
  for (TracePoint3& p : learner_part) {
    p[0] = fit.expert_x + fit.scale * (p[0] - fit.learner_x);
    p[1] = fit.expert_y + fit.scale * (p[1] - fit.learner_y);
  }
  return mean_credit(expert_part, learner_part) * mean_credit(learner_part, expert_part) - 1.0;
}

}  // namespace sc
