#include "tests/render/primitives_scene.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/render/world_label.hpp"

namespace sc::test {
namespace {

void draw_scene(Renderer2D& r, const Camera2D& camera, int variant) {
  r.set_camera(camera);
  // Lot surface and a rotated rectangle (car body) with outline.
  r.fill_rect({{8, 5}, {7.5f, 4.5f}, 0}, Color::hex(0x2a3140));
  r.fill_rect({{variant == 1 ? 4.6f : 4.0f, 3.0f}, {1.6f, 0.8f}, 0.5f}, Color::hex(0x2f6fd8));
  r.outline_rect({{4, 3}, {1.6f, 0.8f}, 0.5f}, Stroke::pixels(2), Color::hex(0xffffff));
  // Polylines: miter join with bevel fallback, round join with round caps, and a closed path.
  const std::array<Vec2f, 4> zig{Vec2f{1, 8}, Vec2f{3, 6}, Vec2f{4, 8.5f}, Vec2f{4.3f, 6}};
  r.polyline(zig, Stroke::world(0.3f), Color::hex(0xf2c94c));
  PathStyle round;
  round.join = LineJoin::round;
  round.cap = LineCap::round;
  const std::array<Vec2f, 4> hook{Vec2f{6, 8.5f}, Vec2f{7, 6.5f}, Vec2f{8.5f, 8}, Vec2f{9, 6}};
  r.polyline(hook, Stroke::world(0.4f), Color::hex(0x27ae60), round);
  PathStyle closed;
  closed.closed = true;
  const std::array<Vec2f, 3> tri{Vec2f{11, 1.5f}, Vec2f{14.5f, 2}, Vec2f{12.5f, 4}};
  r.polyline(tri, Stroke::pixels(3), Color::hex(0xeb5757), closed);
  // Circles.
  r.fill_circle({10, 7}, 1.0f, Color::hex(0x9b51e0));
  r.outline_circle({13, 7}, 1.2f, Stroke::pixels(2.5f), Color::hex(0x56ccf2));
  // Dashed line and a translucent ghost ribbon that crosses itself (blended once where it overlaps).
  const std::array<Vec2f, 3> dash{Vec2f{1, 1}, Vec2f{8, 1}, Vec2f{9, 2.5f}};
  r.dashed_polyline(dash, Stroke::pixels(2), {10, 6}, Color::hex(0xffffff, 0.9f));
  std::vector<Vec2f> loop;
  for (int i = 0; i <= 48; ++i) {
    const float t = static_cast<float>(i) / 48.0f * 2 * std::numbers::pi_v<float>;
    loop.push_back({8 + 2.5f * std::sin(t), 4.5f + 1.3f * std::sin(2 * t)});  // figure eight
  }
  r.ghost_ribbon(loop, Stroke::world(0.7f), Color::hex(0x5b9bff, 0.35f), round);
  // Arrows: world-unit and pixel-unit heads.
  r.arrow({11, 9}, {14.5f, 9}, Stroke::world(0.12f), {0.7f, 0.6f}, Color::hex(0xf2994a));
  r.arrow({15, 8.5f}, {15, 5.5f}, Stroke::pixels(2), {12, 10}, Color::hex(0xf2994a));
  r.fill_polygon(std::array<Vec2f, 5>{Vec2f{1, 3}, Vec2f{2, 2.5f}, Vec2f{2.6f, 3.4f}, Vec2f{2, 4.4f}, Vec2f{1.1f, 4}},
                 Color::hex(0x6fcf97, 0.8f));
}

}  // namespace

RgbaImage render_primitives_scene(GlContext& context, int variant, int frames) {
  context.make_current();
  ImGuiLayer imgui(context);
  Renderer2D renderer(context);
  const float w = static_cast<float>(context.width()), h = static_cast<float>(context.height());
  const Camera2D camera({0, 0, 16, 10}, {0, 0, w, h}, WorldYAxis::down);
  for (int frame = 0; frame < frames; ++frame) {
    imgui.begin_frame(1.0 / 60.0);
    renderer.begin_frame(Color::hex(0x14181f));
    draw_scene(renderer, camera, variant);
    LabelStyle label;
    label.anchor = LabelAnchor::above;
    label.background = Color::hex(0x000000, 0.6f);
    draw_world_label(camera, {4, 1.9f}, "car 1", label);
    renderer.end_frame();
    imgui.end_frame();
    context.present();
  }
  return context.read_rgba();
}

}  // namespace sc::test
