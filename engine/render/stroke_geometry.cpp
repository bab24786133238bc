#include "engine/render/stroke_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>

namespace sc {
namespace {

float length(Vec2f v) { return std::sqrt(dot(v, v)); }
Vec2f normalized(Vec2f v) {
  const float len = length(v);
  return len > 0 ? v * (1.0f / len) : Vec2f{};
}
Vec2f left_normal(Vec2f dir) { return {-dir.y, dir.x}; }

void piece(ConvexPieces& out, std::initializer_list<Vec2f> corners, std::initializer_list<bool> outline) {
  auto flag = outline.begin();
  for (const Vec2f& c : corners) out.add_corner(c, *flag++);
  out.end_piece();
}

// Adds the corners of an arc around `center` from direction `from` by `sweep` radians (both ends included) to
// the open piece, the edges between them outline.
void add_arc_corners(ConvexPieces& out, Vec2f center, float radius, Vec2f from, float sweep, float max_chord_error) {
  const int full = circle_segments(radius, max_chord_error);
  const int steps = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) / (2 * std::numbers::pi_v<float>)*full)));
  const float start = std::atan2(from.y, from.x);
  for (int i = 0; i <= steps; ++i) {
    const float angle = start + sweep * static_cast<float>(i) / static_cast<float>(steps);
    out.add_corner(center + Vec2f{std::cos(angle), std::sin(angle)} * radius, i < steps);
  }
}

std::vector<Vec2f> distinct_points(std::span<const Vec2f> points, bool closed) {
  std::vector<Vec2f> result;
  for (const Vec2f& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    if (result.empty() || length(p - result.back()) > 1e-6f) result.push_back(p);
  }
  if (closed && result.size() > 2 && length(result.front() - result.back()) <= 1e-6f) result.pop_back();
  return result;
}

// The wedge filling the outer side of a bend; its sides along the segments' ends are seams.
void append_join(ConvexPieces& out, Vec2f pivot, Vec2f dir_in, Vec2f dir_out, float half, const PathStyle& style,
                 float max_chord_error) {
  const float turn = cross(dir_in, dir_out);
  if (std::fabs(turn) < 1e-6f && dot(dir_in, dir_out) > 0) return;  // straight on: the quads already meet
  const float side = turn > 0 ? -1.0f : 1.0f;                       // the outer side of the bend
  const Vec2f n_in = left_normal(dir_in) * side, n_out = left_normal(dir_out) * side;
  const Vec2f a = pivot + n_in * half, b = pivot + n_out * half;
  if (style.join == LineJoin::round) {
    const float sweep = std::atan2(cross(n_in, n_out), dot(n_in, n_out));
    out.add_corner(pivot, false);
    add_arc_corners(out, pivot, half, n_in, sweep, max_chord_error);
    out.end_piece();  // the last arc corner's edge back to the pivot is a seam
    return;
  }
  const Vec2f miter_dir = normalized(n_in + n_out);
  const float cos_half = dot(miter_dir, n_in);
  if (cos_half > 1e-4f && 1.0f / cos_half <= style.miter_limit) {
    piece(out, {pivot, a, pivot + miter_dir * (half / cos_half), b}, {false, true, true, false});
  } else {
    piece(out, {pivot, a, b}, {false, true, false});  // bevel
  }
}

// A cap beyond `end`; its side along the segment's end is a seam.
void append_cap(ConvexPieces& out, Vec2f end, Vec2f outward, float half, LineCap cap, float max_chord_error) {
  const Vec2f n = left_normal(outward) * half;
  if (cap == LineCap::square) {
    const Vec2f ext = outward * half;
    piece(out, {end + n, end + n + ext, end - n + ext, end - n}, {true, true, true, false});
  } else if (cap == LineCap::round) {
    add_arc_corners(out, end, half, n, -std::numbers::pi_v<float>, max_chord_error);
    out.end_piece();  // the last arc corner's edge back to the first is the seam
  }
}

}  // namespace

int circle_segments(float radius, float max_chord_error) {
  const float r = std::fabs(radius);
  if (!(r > max_chord_error) || !(max_chord_error > 0)) return 12;
  const float step = 2.0f * std::acos(1.0f - max_chord_error / r);
  return std::clamp(static_cast<int>(std::ceil(2 * std::numbers::pi_v<float> / step)), 12, 256);
}

void append_polyline(ConvexPieces& out, std::span<const Vec2f> points, float width, const PathStyle& style,
                     float max_chord_error) {
  if (!(width > 0)) return;
  const float half = width * 0.5f;
  const std::vector<Vec2f> pts = distinct_points(points, style.closed);
  if (pts.size() == 1 && style.cap == LineCap::round && !style.closed) {
    append_circle(out, pts[0], half, max_chord_error);
    return;
  }
  if (pts.size() < 2) return;
  const bool closed = style.closed && pts.size() > 2;
  const std::size_t segments = closed ? pts.size() : pts.size() - 1;
  const bool butt = !closed && style.cap == LineCap::butt;  // the ends are outline, not seams with a cap
  for (std::size_t i = 0; i < segments; ++i) {
    const Vec2f p = pts[i], q = pts[(i + 1) % pts.size()];
    const Vec2f n = left_normal(normalized(q - p)) * half;
    piece(out, {p + n, q + n, q - n, p - n}, {true, butt && i + 1 == segments, true, butt && i == 0});
  }
  for (std::size_t i = closed ? 0 : 1; i < (closed ? pts.size() : pts.size() - 1); ++i) {
    const Vec2f prev = pts[(i + pts.size() - 1) % pts.size()], here = pts[i], next = pts[(i + 1) % pts.size()];
    append_join(out, here, normalized(here - prev), normalized(next - here), half, style, max_chord_error);
  }
  if (!closed) {
    append_cap(out, pts.front(), normalized(pts[0] - pts[1]), half, style.cap, max_chord_error);
    append_cap(out, pts.back(), normalized(pts.back() - pts[pts.size() - 2]), half, style.cap, max_chord_error);
  }
}

std::vector<std::vector<Vec2f>> dash_polyline(std::span<const Vec2f> points, float dash_length, float gap_length) {
  std::vector<std::vector<Vec2f>> dashes;
  if (!(dash_length > 0) || !(gap_length >= 0) || points.size() < 2) return dashes;
  bool on = true;
  float left = dash_length;  // length remaining in the current dash or gap
  std::vector<Vec2f> current{points[0]};
  for (std::size_t i = 1; i < points.size(); ++i) {
    Vec2f from = points[i - 1];
    const Vec2f to = points[i];
    float remaining = length(to - from);
    const Vec2f dir = normalized(to - from);
    while (remaining >= left) {
      from = from + dir * left;
      remaining -= left;
      if (on) {
        current.push_back(from);
        dashes.push_back(std::move(current));
        current.clear();
      } else {
        current = {from};
      }
      on = !on;
      left = on ? dash_length : gap_length;
      if (left <= 0) {  // zero gap: the next dash starts right here
        on = true;
        left = dash_length;
        current = {from};
      }
    }
    left -= remaining;
    if (on) current.push_back(to);
  }
  if (on && current.size() >= 2) dashes.push_back(std::move(current));
  return dashes;
}

void append_convex_polygon(ConvexPieces& out, std::span<const Vec2f> corners) {
  for (const Vec2f& c : corners) out.add_corner(c, true);
  out.end_piece();
}

void append_circle(ConvexPieces& out, Vec2f center, float radius, float max_chord_error) {
  if (!(radius > 0)) return;
  const int n = circle_segments(radius, max_chord_error);
  for (int i = 0; i < n; ++i) {
    const float a = 2 * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(n);
    out.add_corner(center + Vec2f{std::cos(a), std::sin(a)} * radius, true);
  }
  out.end_piece();
}

void append_ring(ConvexPieces& out, Vec2f center, float radius, float width, float max_chord_error) {
  if (!(radius > 0) || !(width > 0)) return;
  const float outer = radius + width * 0.5f, inner = std::max(0.0f, radius - width * 0.5f);
  const int n = circle_segments(outer, max_chord_error);
  for (int i = 0; i < n; ++i) {
    const float a0 = 2 * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(n);
    const float a1 = 2 * std::numbers::pi_v<float> * static_cast<float>(i + 1) / static_cast<float>(n);
    const Vec2f d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
    piece(out, {center + d0 * inner, center + d0 * outer, center + d1 * outer, center + d1 * inner},
          {false, true, false, true});
  }
}

std::vector<Vec2f> rect_corners(const RotatedRect& rect) {
  const Vec2f ax{std::cos(rect.angle), std::sin(rect.angle)}, ay{-ax.y, ax.x};
  const Vec2f ex = ax * rect.half_size.x, ey = ay * rect.half_size.y;
  return {rect.center - ex - ey, rect.center + ex - ey, rect.center + ex + ey, rect.center - ex + ey};
}

void append_arrow(ConvexPieces& out, Vec2f from, Vec2f to, float width, float head_length, float head_width) {
  const float total = length(to - from);
  if (!(total > 0)) return;
  const Vec2f dir = normalized(to - from);
  const float head = std::min(head_length, total);
  const Vec2f base = to - dir * head;
  if (total - head > 0 && width > 0) {  // the shaft's end under the head is a seam with it
    const Vec2f n = left_normal(dir) * (width * 0.5f);
    piece(out, {from + n, base + n, base - n, from - n}, {true, false, true, true});
  }
  const Vec2f side = left_normal(dir) * (head_width * 0.5f);
  piece(out, {to, base + side, base - side}, {true, true, true});
}

}  // namespace sc
