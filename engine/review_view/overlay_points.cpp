#include "engine/review_view/overlay_points.hpp"

#include <algorithm>
#include <cmath>

namespace sc::review_view {

std::vector<ImVec2> fit_into_box(const std::vector<ImVec2>& points, ImVec2 o, ImVec2 size, const OverlayBounds& b) {
  constexpr float kPad = 10.0f;
  const float scale = std::min((size.x - 2 * kPad) / std::max(1e-3f, b.hi.x - b.lo.x),
                               (size.y - 2 * kPad) / std::max(1e-3f, b.hi.y - b.lo.y));
  std::vector<ImVec2> out;
  for (const ImVec2& p : points)
    out.emplace_back(o.x + size.x * 0.5f + (p.x - (b.lo.x + b.hi.x) * 0.5f) * scale,
                     o.y + size.y * 0.5f + (p.y - (b.lo.y + b.hi.y) * 0.5f) * scale);
  return out;
}

std::vector<ImVec2> thinned(const std::vector<ImVec2>& points, float spacing) {
  std::vector<ImVec2> out;
  for (const ImVec2& p : points) {
    if (!out.empty()) {
      const float dx = p.x - out.back().x, dy = p.y - out.back().y;
      if (dx * dx + dy * dy < spacing * spacing) continue;
    }
    out.push_back(p);
  }
  if (!points.empty() && (out.size() < 2 || out.back().x != points.back().x || out.back().y != points.back().y))
    out.push_back(points.back());
  return out;
}

// The pieces' ends overlap where the path is split.
void draw_thick_path(ImDrawList& d, const std::vector<ImVec2>& points, ImU32 color, float thickness) {
  constexpr float kSharpTurnCosine = -0.3f;  // a turn of more than ~107 degrees
  std::size_t begin = 0;
  for (std::size_t i = 1; i + 1 <= points.size(); ++i) {
    bool split = i + 1 == points.size();
    if (!split) {
      const ImVec2 a(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y),
          b(points[i + 1].x - points[i].x, points[i + 1].y - points[i].y);
      const float norms = std::sqrt((a.x * a.x + a.y * a.y) * (b.x * b.x + b.y * b.y));
      split = norms > 0.0f && (a.x * b.x + a.y * b.y) / norms < kSharpTurnCosine;
    }
    if (!split) continue;
    d.AddPolyline(points.data() + begin, static_cast<int>(i - begin + 1), color, ImDrawFlags_None, thickness);
    begin = i;
  }
}

void OverlayBounds::include(const std::vector<ImVec2>& points) {
  for (const ImVec2& p : points) {
    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
  }
}

void draw_overlay_points(ImDrawList& d, ImVec2 o, ImVec2 size, const std::vector<ImVec2>& learner,
                         const std::vector<ImVec2>& reference, const OverlayBounds& bounds, ImU32 band) {
  d.AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(28, 33, 43, 255), 6.0f);
  if (learner.size() < 2 || reference.size() < 2) return;
  const std::vector<ImVec2> e = thinned(fit_into_box(reference, o, size, bounds), 5.0f),
                            l = thinned(fit_into_box(learner, o, size, bounds), 1.5f);
  draw_thick_path(d, e, band, kOverlayBandWidth);
  draw_thick_path(d, l, kOverlayLearner, kOverlayLearnerWidth);
  d.AddCircleFilled(l.back(), 4.0f, kOverlayLearner);
}

void draw_hand_overlay(ImDrawList& d, ImVec2 first, ImVec2 second, ImVec2 box, const HandOverlay& overlay) {
  OverlayBounds bounds;
  bounds.include(overlay.learner);
  bounds.include(overlay.guide);
  bounds.include(overlay.hand);
  draw_overlay_points(d, first, box, overlay.learner, overlay.guide, bounds, kOverlayGuide);
  draw_overlay_points(d, second, box, overlay.learner, overlay.hand, bounds, kOverlayHand);
}

void draw_part_overlay(ImDrawList& d, ImVec2 o, ImVec2 size, const PartOverlay& overlay) {
  OverlayBounds bounds;
  bounds.include(overlay.learner);
  bounds.include(overlay.expert);
  draw_overlay_points(d, o, size, overlay.learner, overlay.expert, bounds, kOverlayGuide);
  if (overlay.last <= overlay.first || overlay.last >= overlay.learner.size()) return;
  const std::vector<ImVec2> part(overlay.learner.begin() + static_cast<std::ptrdiff_t>(overlay.first),
                                 overlay.learner.begin() + static_cast<std::ptrdiff_t>(overlay.last) + 1);
  draw_thick_path(d, thinned(fit_into_box(part, o, size, bounds), 1.5f), kOverlayPart, kOverlayPartWidth);
}

}  // namespace sc::review_view
