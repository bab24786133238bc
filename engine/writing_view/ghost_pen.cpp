#include "engine/writing_view/ghost_pen.hpp"

#include <algorithm>
#include <cmath>

namespace sc::writing_view {

double ghost_pen_duration(std::size_t points, double steps_per_second) {
  if (points < 2 || steps_per_second <= 0.0) return 0.0;
  return static_cast<double>(points - 1) / steps_per_second;
}

GhostPenFrame ghost_pen_at(std::span<const writing::TracePoint> path, double seconds, double steps_per_second) {
  GhostPenFrame frame;
  if (path.empty()) {
    frame.finished = true;
    frame.progress = 1.0;
    return frame;
  }
  const double steps = static_cast<double>(path.size() - 1);
  const double done = std::clamp(seconds * steps_per_second, 0.0, steps);
  const auto whole = static_cast<std::size_t>(std::floor(done));
  const double fraction = done - static_cast<double>(whole);
  frame.written.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(whole) + 1);
  writing::TracePoint tip = path[whole];
  if (whole + 1 < path.size() && fraction > 0.0) {
    const writing::TracePoint& next = path[whole + 1];
    tip = {tip.x + (next.x - tip.x) * fraction, tip.y + (next.y - tip.y) * fraction, next.pen};
    frame.written.push_back(tip);
    frame.pen_down = next.pen;
  } else {
    // Resting on a point: the pen is down if it arrived drawing (the first point: if the next step draws).
    frame.pen_down = whole > 0 ? path[whole].pen : (path.size() > 1 ? path[1].pen : true);
  }
  frame.tip = {static_cast<float>(tip.x), static_cast<float>(tip.y)};
  frame.progress = steps > 0.0 ? done / steps : 1.0;
  frame.finished = done >= steps;
  return frame;
}

}  // namespace sc::writing_view
