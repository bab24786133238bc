#include "engine/writing_view/canvas_painter.hpp"

#include <array>

#include "engine/writing_view/canvas_geometry.hpp"

namespace sc::writing_view {
namespace {

PathStyle round_path() {
  PathStyle style;
  style.join = LineJoin::round;
  style.cap = LineCap::round;
  return style;
}

// Dash lengths of pen-up hops, in canvas pixels.
constexpr DashPattern kHopDashes{4.0f, 4.0f};

void paint_hops(Renderer2D& renderer, const std::vector<std::vector<Vec2f>>& hops, Color color, float width) {
  for (const auto& hop : hops) renderer.dashed_polyline(hop, Stroke::world(width), kHopDashes, color, round_path());
}

}  // namespace

Vec2f first_pen_down(std::span<const writing::TracePoint> path) {
  if (path.empty()) return {};
  std::size_t i = 1;
  while (i < path.size() && !path[i].pen) ++i;
  const writing::TracePoint& p = i < path.size() ? path[i - 1] : path.front();
  return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

void paint_paper(Renderer2D& renderer, const WritingCanvasLook& look) {
  const WorldRect visible = renderer.camera().visible_world();
  const Vec2f world_center{(visible.min_x + visible.max_x) * 0.5f, (visible.min_y + visible.max_y) * 0.5f};
  const Vec2f world_half{(visible.max_x - visible.min_x) * 0.5f, (visible.max_y - visible.min_y) * 0.5f};
  renderer.fill_rect({world_center, world_half, 0.0f}, look.desk);

  const WorldRect canvas = canvas_rect();
  const Vec2f center{canvas.max_x * 0.5f, canvas.max_y * 0.5f};
  const Vec2f half{canvas.max_x * 0.5f, canvas.max_y * 0.5f};
  renderer.fill_rect({center + Vec2f{1.5f, 2.0f}, half, 0.0f}, Color::hex(0x000000, 0.25f));  // a soft shadow
  renderer.fill_rect({center, half, 0.0f}, look.paper);
  for (float y = look.rule_spacing; y < canvas.max_y; y += look.rule_spacing) {
    const std::array<Vec2f, 2> rule{Vec2f{canvas.min_x, y}, Vec2f{canvas.max_x, y}};
    const bool baseline = y == static_cast<float>(writing::kStartY);
    renderer.polyline(rule, Stroke::world(baseline ? 1.0f : 0.6f), baseline ? look.baseline : look.rule);
  }
  renderer.outline_rect({center, half, 0.0f}, Stroke::world(1.0f), look.paper_edge);
  // The start position: a small tick on the left edge, where every word begins.
  const Vec2f start{static_cast<float>(writing::kStartX), static_cast<float>(writing::kStartY)};
  const std::array<Vec2f, 3> tick{start + Vec2f{0.0f, -7.0f}, start + Vec2f{5.0f, 0.0f}, start + Vec2f{0.0f, 7.0f}};
  renderer.fill_polygon(tick, look.start_mark);
}

void paint_ink(Renderer2D& renderer, std::span<const writing::TracePoint> trace, Color color, float width) {
  const InkPaths paths = split_ink(trace);
  for (const auto& run : paths.runs) renderer.polyline(run, Stroke::world(width), color, round_path());
  for (const Vec2f dot : paths.dots) renderer.fill_circle(dot, width * 0.5f, color);
}

void paint_guide(Renderer2D& renderer, std::span<const writing::TracePoint> gold, const WritingCanvasLook& look) {
  // A ghost ribbon rather than a polyline: a translucent line that crosses itself would darken at every
  // crossing, and the guide should read as one even, faint word.
  const InkPaths paths = split_ink(gold);
  for (const auto& run : paths.runs)
    renderer.ghost_ribbon(run, Stroke::world(look.guide_width), look.guide, round_path());
  for (const Vec2f dot : paths.dots) renderer.fill_circle(dot, look.guide_width * 0.5f, look.guide);
}

void paint_learner_ink(Renderer2D& renderer, std::span<const writing::TracePoint> trace,
                       const WritingCanvasLook& look) {
  paint_ink(renderer, trace, look.ink, look.ink_width);
}

void paint_drill_ribbon(Renderer2D& renderer, std::span<const writing::TracePoint> path,
                        const WritingCanvasLook& look) {
  if (path.empty()) return;
  const InkPaths paths = split_ink(path);
  for (const auto& run : paths.runs)
    renderer.ghost_ribbon(run, Stroke::world(look.ribbon_width), look.ribbon, round_path());
  for (const Vec2f dot : paths.dots) renderer.fill_circle(dot, look.ribbon_width * 0.5f, look.ribbon);
  paint_hops(renderer, paths.hops, look.ribbon_hop, 1.4f);
  const ArrowHead head{look.arrow_length * 0.5f, look.arrow_length * 0.55f};
  for (const auto& run : paths.runs)
    for (const DirectionMark& mark : direction_marks(run, look.arrow_spacing, look.arrow_length))
      renderer.arrow(mark.from, mark.to, Stroke::world(look.arrow_length * 0.14f), head, look.arrow);
  const Vec2f start = first_pen_down(path);
  renderer.fill_circle(start, look.start_dot_radius, look.start_dot);
  renderer.outline_circle(start, look.start_dot_radius, Stroke::world(1.2f), Color::hex(0xffffff, 0.9f));
}

void paint_ghost_pen(Renderer2D& renderer, const GhostPenFrame& frame, const WritingCanvasLook& look) {
  if (frame.written.empty()) return;
  const InkPaths paths = split_ink(frame.written);
  paint_hops(renderer, paths.hops, look.ghost_hop, 1.4f);
  for (const auto& run : paths.runs)
    renderer.polyline(run, Stroke::world(look.ghost_ink_width), look.ghost_ink, round_path());
  for (const Vec2f dot : paths.dots) renderer.fill_circle(dot, look.ghost_ink_width * 0.5f, look.ghost_ink);
  if (frame.pen_down) {
    renderer.fill_circle(frame.tip, look.ghost_tip_radius, look.ghost_tip);
    renderer.outline_circle(frame.tip, look.ghost_tip_radius, Stroke::world(1.2f), Color::hex(0xffffff, 0.9f));
  } else {
    renderer.outline_circle(frame.tip, look.ghost_tip_radius, Stroke::world(1.6f), look.ghost_tip);
  }
}

}  // namespace sc::writing_view
