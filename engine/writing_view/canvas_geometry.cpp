#include "engine/writing_view/canvas_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace sc::writing_view {
namespace {

Vec2f vec(const writing::TracePoint& p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }

bool same_position(const writing::TracePoint& a, const writing::TracePoint& b) { return a.x == b.x && a.y == b.y; }

float distance(Vec2f a, Vec2f b) { return std::hypot(b.x - a.x, b.y - a.y); }

}  // namespace

WorldRect canvas_rect() {
  return {0.0f, 0.0f, static_cast<float>(writing::kCanvasWidth), static_cast<float>(writing::kCanvasHeight)};
}

Camera2D writing_canvas_camera(PixelViewport viewport, float margin) {
  const WorldRect canvas = canvas_rect();
  return Camera2D({canvas.min_x - margin, canvas.min_y - margin, canvas.max_x + margin, canvas.max_y + margin},
                  viewport, WorldYAxis::down);
}

std::vector<Vec2f> to_vec2f(std::span<const writing::TracePoint> trace) {
  std::vector<Vec2f> out;
  out.reserve(trace.size());
  for (const auto& p : trace) out.push_back(vec(p));
  return out;
}

InkPaths split_ink(std::span<const writing::TracePoint> trace) {
  InkPaths paths;
  // Walk the segments; a chain continues while the pen state stays the same.
  std::size_t i = 1;
  while (i < trace.size()) {
    const bool pen = trace[i].pen;
    std::size_t end = i;
    while (end + 1 < trace.size() && trace[end + 1].pen == pen) ++end;
    // The chain covers points i-1 .. end.
    std::vector<Vec2f> chain;
    bool moves = false;
    for (std::size_t k = i - 1; k <= end; ++k) {
      if (k >= i && !same_position(trace[k], trace[k - 1])) moves = true;
      if (chain.empty() || !same_position(trace[k], trace[k - 1])) chain.push_back(vec(trace[k]));
    }
    if (pen) {
      if (moves)
        paths.runs.push_back(std::move(chain));
      else
        paths.dots.push_back(chain.front());
    } else if (moves) {
      paths.hops.push_back(std::move(chain));
    }
    i = end + 1;
  }
  return paths;
}

float path_length(std::span<const Vec2f> path) {
  float length = 0.0f;
  for (std::size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

Vec2f point_at_length(std::span<const Vec2f> path, float s) {
  if (path.empty()) return {};
  if (s <= 0.0f) return path.front();
  float walked = 0.0f;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const float step = distance(path[i - 1], path[i]);
    if (walked + step >= s && step > 0.0f) {
      const float t = (s - walked) / step;
      return path[i - 1] + (path[i] - path[i - 1]) * t;
    }
    walked += step;
  }
  return path.back();
}

std::vector<DirectionMark> direction_marks(std::span<const Vec2f> path, float spacing, float length, float window) {
  std::vector<DirectionMark> marks;
  if (path.size() < 2 || spacing <= 0.0f) return marks;
  const float total = path_length(path);
  for (float s = spacing * 0.5f; s <= total; s += spacing) {
    const Vec2f behind = point_at_length(path, std::max(0.0f, s - window));
    const Vec2f ahead = point_at_length(path, std::min(total, s + window));
    const float chord = distance(behind, ahead);
    if (chord <= 1e-4f) continue;  // the path turns back on itself here: no meaningful direction
    const Vec2f unit = (ahead - behind) * (1.0f / chord);
    const Vec2f at = point_at_length(path, s);
    marks.push_back({at - unit * (length * 0.5f), at + unit * (length * 0.5f)});
  }
  return marks;
}

}  // namespace sc::writing_view
