#include "teaching/drills/drill_plan.hpp"

#include <string>

#include "engine/core/error.hpp"

namespace sc {
namespace {

const StepSequence& checked_expert(const DrillSegment& s, std::size_t index, const std::vector<StepSequence>& experts) {
  const std::string where = "drill segment " + std::to_string(index);
  if (s.expert < 0 || static_cast<std::size_t>(s.expert) >= experts.size()) {
    throw InputError(where, "expert index " + std::to_string(s.expert) + " is outside the " +
                                std::to_string(experts.size()) + " expert trajectories");
  }
  const StepSequence& e = experts[static_cast<std::size_t>(s.expert)];
  if (s.begin < 0 || s.end <= s.begin || s.end > e.length()) {
    throw InputError(where, "interval [" + std::to_string(s.begin) + ", " + std::to_string(s.end) +
                                ") is empty or outside expert " + std::to_string(s.expert) + " of length " +
                                std::to_string(e.length()));
  }
  if (e.state_dim > 0 && e.states.size() < static_cast<std::size_t>(e.length() * e.state_dim)) {
    throw InputError(where, "expert " + std::to_string(s.expert) + " has fewer states than actions");
  }
  return e;
}

}  // namespace

int DrillPlan::length() const {
  int total = 0;
  for (const auto& s : segments) total += s.length();
  return total;
}

std::vector<int> DrillPlan::skills() const {
  std::vector<int> out;
  out.reserve(segments.size());
  for (const auto& s : segments) out.push_back(s.skill);
  return out;
}

std::vector<int> DrillPlan::segment_starts() const {
  std::vector<int> out;
  out.reserve(segments.size());
  int t = 0;
  for (const auto& s : segments) {
    out.push_back(t);
    t += s.length();
  }
  return out;
}

Segmentation plan_segmentation(const DrillPlan& plan) {
  Segmentation out;
  int t = 0;
  for (const auto& s : plan.segments) {
    if (s.length() <= 0) continue;  // Segmentation drops empty segments
    out.segments.push_back({s.skill, t, t + s.length()});
    t += s.length();
  }
  return out;
}

std::vector<float> drill_initial_state(const DrillPlan& plan, const std::vector<StepSequence>& experts) {
  if (plan.segments.empty()) throw InputError("drill", "the plan has no segments");
  const DrillSegment& first = plan.segments.front();
  const StepSequence& e = checked_expert(first, 0, experts);
  const auto dim = static_cast<std::size_t>(e.state_dim);
  const auto from = e.states.begin() + static_cast<long>(static_cast<std::size_t>(first.begin) * dim);
  return std::vector<float>(from, from + static_cast<long>(dim));
}

StepSequence concatenate_expert_steps(const DrillPlan& plan, const std::vector<StepSequence>& experts) {
  if (plan.segments.empty()) throw InputError("drill", "the plan has no segments");
  StepSequence out;
  for (std::size_t i = 0; i < plan.segments.size(); ++i) {
    const DrillSegment& s = plan.segments[i];
    const StepSequence& e = checked_expert(s, i, experts);
    if (i == 0) {
      out.state_dim = e.state_dim;
      out.action_dim = e.action_dim;
    } else if (e.state_dim != out.state_dim || e.action_dim != out.action_dim) {
      throw InputError("drill segment " + std::to_string(i),
                       "expert " + std::to_string(s.expert) + " has other state/action dimensions");
    }
    const auto sd = static_cast<long>(e.state_dim);
    const auto ad = static_cast<long>(e.action_dim);
    out.states.insert(out.states.end(), e.states.begin() + s.begin * sd, e.states.begin() + s.end * sd);
    out.actions.insert(out.actions.end(), e.actions.begin() + s.begin * ad, e.actions.begin() + s.end * ad);
  }
  return out;
}

}  // namespace sc
