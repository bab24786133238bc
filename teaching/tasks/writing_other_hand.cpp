#include "teaching/tasks/writing_other_hand.hpp"

#include <algorithm>
#include <cmath>

#include "teaching/tasks/writing_execution.hpp"

namespace sc {
namespace {

struct Frame {
  double x0 = 0.0, y0 = 0.0, width = 1.0, height = 1.0;
};

Frame frame_of(const std::vector<writing::TracePoint>& pts) {
  double lo_x = pts.front().x, hi_x = lo_x, lo_y = pts.front().y, hi_y = lo_y;
  for (const auto& p : pts) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  return {pts.front().x, pts.front().y, std::max(hi_x - lo_x, 1.0), std::max(hi_y - lo_y, 1.0)};
}

// `pts` relative to its first point, scaled so that its bounding box has `target`'s size.
std::vector<TracePoint3> in_frame(const std::vector<writing::TracePoint>& pts, const Frame& target) {
  const Frame own = frame_of(pts);
  std::vector<TracePoint3> out;
  out.reserve(pts.size());
  for (const auto& p : pts)
    out.push_back({(p.x - own.x0) * target.width / own.width, (p.y - own.y0) * target.height / own.height, 0.0});
  return out;
}

std::vector<writing::TracePoint> step_positions(const StepSequence& steps) {
  std::vector<writing::TracePoint> out;
  for (const TracePoint3& p : writing_trace_points(steps)) out.push_back({p[0], p[1], true});
  return out;
}

}  // namespace

StepAlignment align_same_word(const StepSequence& clean, const StepSequence& copy) {
  return align_same_word(step_positions(clean), step_positions(copy));
}

StepAlignment align_same_word(const std::vector<writing::TracePoint>& clean,
                              const std::vector<writing::TracePoint>& copy) {
  const Frame frame = frame_of(clean);
  return align_traces(in_frame(clean, frame), in_frame(copy, frame));
}

CarriedBoundaries carried_boundaries(const WrittenWord& clean, const WrittenWord& copy,
                                     const std::vector<int>& clean_boundaries) {
  CarriedBoundaries out;
  if (clean.points.empty() || copy.points.empty()) {
    out.kept.assign(clean_boundaries.size(), false);
    return out;
  }
  const StepAlignment path = align_same_word(clean.points, copy.points);
  const int last = static_cast<int>(copy.points.size()) - 1;
  for (int b : clean_boundaries) {
    const int at = aligned_span(path, b, b + 1).first;
    const bool keep = at > (out.boundaries.empty() ? 0 : out.boundaries.back()) && at < last;
    out.kept.push_back(keep);
    if (keep) out.boundaries.push_back(at);
  }
  return out;
}

}  // namespace sc
