#include "engine/writing/infill.hpp"

#include <cmath>
#include <stdexcept>

namespace sc::writing {
namespace {

bool needs_split(double ax, double ay, double bx, double by) {
  // The reference tests |dy| > 1 first, then |dx| > 1; both insert the same midpoint, so one test suffices.
  return std::fabs(by - ay) > 1.0 || std::fabs(bx - ax) > 1.0;
}

// Recursive form of the reference's insert-and-recheck loop: splitting (a, b) at m and re-checking (a, m)
// before moving on to (m, b) emits exactly the same points in the same order.
void emit_infilled(const Point2& a, const Point2& b, std::vector<Point2>& out) {
  if (needs_split(a.x, a.y, b.x, b.y)) {
    const Point2 m{(b.x + a.x) / 2, (b.y + a.y) / 2};
    emit_infilled(a, m, out);
    emit_infilled(m, b, out);
  } else {
    out.push_back(b);
  }
}

void emit_infilled_trace(const TracePoint& a, const TracePoint& b, double ta, double tb, bool timed, TimedTrace& out) {
  if (needs_split(a.x, a.y, b.x, b.y)) {
    const TracePoint m{(b.x + a.x) / 2, (b.y + a.y) / 2, b.pen};
    const double tm = (tb + ta) / 2;
    emit_infilled_trace(a, m, ta, tm, timed, out);
    emit_infilled_trace(m, b, tm, tb, timed, out);
  } else {
    out.points.push_back(b);
    if (timed) out.times.push_back(tb);
  }
}

}  // namespace

std::vector<Point2> infill_reference(const std::vector<Point2>& points) {
  std::vector<Point2> out;
  if (points.empty()) return out;
  out.reserve(points.size() * 2);
  out.push_back(points.front());
  for (std::size_t i = 0; i + 1 < points.size(); ++i) emit_infilled(points[i], points[i + 1], out);
  return out;
}

TimedTrace infill_trace(const TimedTrace& trace) {
  const bool timed = !trace.times.empty();
  if (timed && trace.times.size() != trace.points.size())
    throw std::invalid_argument("infill_trace: times and points differ in length");
  TimedTrace out;
  if (trace.points.empty()) return out;
  out.points.push_back(trace.points.front());
  if (timed) out.times.push_back(trace.times.front());
  for (std::size_t i = 0; i + 1 < trace.points.size(); ++i)
    emit_infilled_trace(trace.points[i], trace.points[i + 1], timed ? trace.times[i] : 0.0,
                        timed ? trace.times[i + 1] : 0.0, timed, out);
  return out;
}

std::vector<Point2> pad_to_min_points(std::vector<Point2> points, std::size_t min_points, Rng& rng) {
  if (points.size() < 2) {
    if (points.size() < min_points) throw std::invalid_argument("pad_to_min_points: need at least two points");
    return points;
  }
  while (points.size() < min_points) {
    const auto i = static_cast<std::size_t>(rng.below(points.size() - 1));
    const Point2 m{(points[i + 1].x + points[i].x) / 2, (points[i + 1].y + points[i].y) / 2};
    // Bug fix: the reference inserted at index i, i.e. before p_i.
    points.insert(points.begin() + static_cast<std::ptrdiff_t>(i + 1), m);
  }
  return points;
}

}  // namespace sc::writing
