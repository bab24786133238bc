#include "engine/parking_view/teaching_overlays.hpp"

#include <cmath>

namespace sc {
namespace {

Vec2f position(const PathSample& s) { return {static_cast<float>(s.vehicle.x), static_cast<float>(s.vehicle.y)}; }

float distance(Vec2f a, Vec2f b) { return std::hypot(b.x - a.x, b.y - a.y); }

double run_length(const ParkingPath& path, const PathRun& run) {
  double length = 0.0;
  for (std::size_t i = run.first; i < run.last; ++i)
    length += distance(position(path.samples[i]), position(path.samples[i + 1]));
  return length;
}

// Arrows every `spacing` metres along points[first..last], pointing along the way the car moved.
void paint_direction_arrows(Renderer2D& r, std::span<const Vec2f> points, float spacing, Color color) {
  if (points.size() < 2) return;
  float next = spacing * 0.5f;  // first arrow half a spacing in, so short runs still get one
  float travelled = 0.0f;
  const float arrow_length = 1.1f;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const float segment = distance(points[i], points[i + 1]);
    while (segment > 1e-6f && travelled + segment >= next) {
      const float along = (next - travelled) / segment;
      const Vec2f dir = (points[i + 1] - points[i]) * (1.0f / segment);
      const Vec2f mid = points[i] + (points[i + 1] - points[i]) * along;
      r.arrow(mid - dir * (arrow_length / 2), mid + dir * (arrow_length / 2), Stroke::world(0.16f), {0.7f, 0.8f},
              color);
      next += spacing;
    }
    travelled += segment;
  }
}

}  // namespace

std::vector<PathRun> split_by_direction(const ParkingPath& path, double min_length) {
  std::vector<PathRun> runs;
  const auto& s = path.samples;
  if (s.size() < 2) return runs;
  for (std::size_t i = 1; i < s.size(); ++i) {
    // The direction of the sub-step that ends at sample i: the sign of the displacement along the heading.
    const double dx = s[i].vehicle.x - s[i - 1].vehicle.x, dy = s[i].vehicle.y - s[i - 1].vehicle.y;
    const double along = dx * std::cos(s[i - 1].vehicle.heading) + dy * std::sin(s[i - 1].vehicle.heading);
    const bool moving = std::fabs(along) > 1e-9;
    const bool reversing = moving ? along < 0 : (!runs.empty() && runs.back().reversing);
    if (runs.empty() || runs.back().reversing != reversing)
      runs.push_back({i - 1, i, reversing});
    else
      runs.back().last = i;
  }
  // Merge runs too short to be a manoeuvre into their predecessor (or successor for the first run).
  std::vector<PathRun> merged;
  for (const PathRun& run : runs) {
    if (!merged.empty() && (run_length(path, run) < min_length || merged.back().reversing == run.reversing))
      merged.back().last = run.last;
    else
      merged.push_back(run);
  }
  if (merged.size() > 1 && run_length(path, merged.front()) < min_length) {
    merged[1].first = merged.front().first;
    merged.erase(merged.begin());
  }
  return merged;
}

void paint_trail(Renderer2D& r, std::span<const Vec2f> positions, const TrailStyle& style) {
  if (positions.size() < 2) return;
  PathStyle round;
  round.join = LineJoin::round;
  round.cap = LineCap::round;
  r.polyline(positions, Stroke::world(style.width), style.color, round);
}

void paint_ghost_path(Renderer2D& r, const ParkingPath& path, const GhostPathStyle& style) {
  const std::vector<Vec2f> points = path_points(path);
  PathStyle round;
  round.join = LineJoin::round;
  round.cap = LineCap::butt;
  const std::vector<PathRun> runs = split_by_direction(path);
  for (const PathRun& run : runs) {
    const std::span<const Vec2f> part(points.data() + run.first, run.last - run.first + 1);
    r.ghost_ribbon(part, Stroke::world(style.width), run.reversing ? style.reverse : style.forward, round);
  }
  for (const PathRun& run : runs) {
    const std::span<const Vec2f> part(points.data() + run.first, run.last - run.first + 1);
    paint_direction_arrows(r, part, style.arrow_spacing, run.reversing ? style.reverse_arrow : style.forward_arrow);
  }
}

void paint_ghost_car(Renderer2D& r, const ParkingPath& path, double t, float alpha) {
  if (path.samples.empty()) return;
  paint_car(r, car_pose_at(path, t), ghost_car_look(alpha));
}

}  // namespace sc
