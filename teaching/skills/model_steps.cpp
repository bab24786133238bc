#include "teaching/skills/model_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sc {

namespace {

double step_length(const StepSequence& s, int t) {
  double sum = 0.0;
  for (int d = 0; d < s.action_dim; ++d) {
    const double a = s.actions[static_cast<std::size_t>(t * s.action_dim + d)];
    sum += a * a;
  }
  return std::sqrt(sum);
}

void append_group(const StepSequence& in, int begin, int end, double path, ModelSteps& out) {
  const auto ad = static_cast<std::size_t>(in.action_dim);
  for (std::size_t d = 0; d < ad; ++d) {
    double displacement = 0.0;
    for (int t = begin; t < end; ++t) displacement += in.actions[static_cast<std::size_t>(t) * ad + d];
    out.steps.actions.push_back(path > 0.0 ? static_cast<float>(displacement / path) : 0.0f);
  }
  const auto sd = static_cast<std::size_t>(in.state_dim);
  if (sd > 0) {
    auto first = in.states.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(begin) * sd);
    out.steps.states.insert(out.steps.states.end(), first, first + static_cast<std::ptrdiff_t>(sd));
  }
  out.original_begin.push_back(begin);
}

}  // namespace

ModelSteps to_model_steps(const StepSequence& trajectory, double resample_step, double phase) {
  ModelSteps out;
  const int t_len = trajectory.length();
  if (resample_step <= 0.0) {
    out.steps = trajectory;
    out.original_begin.resize(static_cast<std::size_t>(t_len) + 1);
    for (int t = 0; t <= t_len; ++t) out.original_begin[static_cast<std::size_t>(t)] = t;
    return out;
  }
  out.steps.state_dim = trajectory.state_dim;
  out.steps.action_dim = trajectory.action_dim;
  int begin = 0;
  double path = phase;  // counted toward the group's length: a phase shortens the first group
  double walked = 0.0;  // path the group's actions actually cover, for their mean direction
  for (int t = 0; t < t_len; ++t) {
    const double length = step_length(trajectory, t);
    path += length;
    walked += length;
    if (path >= resample_step) {
      append_group(trajectory, begin, t + 1, walked, out);
      begin = t + 1;
      path = walked = 0.0;
    }
  }
  if (begin < t_len) append_group(trajectory, begin, t_len, walked, out);
  out.original_begin.push_back(t_len);
  return out;
}

Segmentation to_original_indices(const Segmentation& model_segments, const ModelSteps& steps) {
  Segmentation out;
  const auto& map = steps.original_begin;
  for (const auto& s : model_segments.segments) {
    const int begin = map[static_cast<std::size_t>(s.begin)];
    const int end = map[static_cast<std::size_t>(s.end)];
    if (end > begin) out.segments.push_back({s.skill, begin, end});
  }
  return out;
}

Segmentation segments_from_boundaries(const std::vector<int>& boundaries, const std::vector<int>& skills, int length) {
  Segmentation out;
  int start = 0;
  for (std::size_t k = 0; k < boundaries.size(); ++k) {
    const int end = k + 1 == boundaries.size() ? length : std::clamp(boundaries[k], 0, length);
    if (end > start) {
      out.segments.push_back({skills[k], start, end});
      start = end;
    }
  }
  return out;
}

}  // namespace sc
