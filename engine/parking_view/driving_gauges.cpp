#include "engine/parking_view/driving_gauges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/input/virtual_joystick.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kDialSweep = 0.75f * kPi;  // each side of "up": 135 degrees

ImU32 rgba(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }
const ImU32 kDialFace = rgba(20, 24, 31, 215);
const ImU32 kDialTrack = rgba(80, 88, 104, 255);
const ImU32 kText = rgba(235, 238, 245, 255);
const ImU32 kCaption = rgba(160, 168, 184, 255);
const ImU32 kForward = rgba(91, 155, 255, 255);   // the ghost path's forward blue
const ImU32 kReverse = rgba(255, 111, 145, 255);  // and its reversing pink
const ImU32 kNeedle = rgba(255, 226, 138, 255);

ImVec2 polar(ImVec2 c, float radius, float angle) {
  return {c.x + radius * std::cos(angle), c.y + radius * std::sin(angle)};
}

void text_centered(ImDrawList& dl, ImVec2 centre, const char* text, ImU32 colour, float size_factor = 1.0f) {
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize() * size_factor;
  const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0.0f, text);
  dl.AddText(font, size, {centre.x - extent.x * 0.5f, centre.y - extent.y * 0.5f}, colour, text);
}

void dial_face(ImDrawList& dl, ImVec2 c, float radius, float s) {
  dl.AddCircleFilled(c, radius, kDialFace, 48);
  dl.AddCircle(c, radius, kDialTrack, 48, 1.5f * s);
}

void caption_below(ImDrawList& dl, ImVec2 c, float radius, const char* caption, float s) {
  text_centered(dl, {c.x, c.y + radius + 12.0f * s}, caption, kCaption, 0.85f);
}

}  // namespace

GaugeLayout layout_driving_gauges(ImVec2 bottom_right, float s) {
  GaugeLayout g;
  g.radius = 46.0f * s;
  const float pad = 14.0f * s, gap = 22.0f * s, caption = 26.0f * s;
  const float width = 3 * 2 * g.radius + 2 * gap + 2 * pad;
  const float height = 2 * g.radius + caption + 2 * pad;
  g.min = {bottom_right.x - width, bottom_right.y - height};
  g.max = bottom_right;
  const float cy = g.min.y + pad + g.radius;
  g.speed = {g.min.x + pad + g.radius, cy};
  g.steering = {g.speed.x + 2 * g.radius + gap, cy};
  g.stick = {g.steering.x + 2 * g.radius + gap, cy};
  return g;
}

void draw_speed_gauge(ImDrawList& dl, ImVec2 c, float radius, double speed, float s) {
  dial_face(dl, c, radius, s);
  const float track = radius * 0.78f;
  const float up = -0.5f * kPi;
  dl.PathArcTo(c, track, up - kDialSweep, up + kDialSweep, 40);
  dl.PathStroke(kDialTrack, 0, 5.0f * s);
  const double value = std::isfinite(speed) ? speed : 0.0;
  const float f = static_cast<float>(std::clamp(value / parking_view::kSpeedGaugeMax, -1.0, 1.0));
  const float angle = up + f * kDialSweep;
  if (std::fabs(f) > 1e-3f) {
    dl.PathArcTo(c, track, std::min(up, angle), std::max(up, angle), 24);
    dl.PathStroke(f > 0 ? kForward : kReverse, 0, 5.0f * s);
  }
  dl.AddLine(c, polar(c, track, angle), kNeedle, 2.5f * s);
  dl.AddCircleFilled(c, 4.0f * s, kNeedle, 12);
  char text[32];
  const bool reversing = value < -0.05;
  std::snprintf(text, sizeof text, reversing ? "R %.1f m/s" : "%.1f m/s",
                std::fabs(value) < 0.05 ? 0.0 : std::fabs(value));
  text_centered(dl, {c.x, c.y + radius * 0.5f}, text, reversing ? kReverse : kText, 0.75f);
  caption_below(dl, c, radius, "speed", s);
}

void draw_steering_gauge(ImDrawList& dl, ImVec2 c, float radius, double steering, float s) {
  dial_face(dl, c, radius, s);
  const double max = parking::kMaxSteering;
  const double value = std::isfinite(steering) ? std::clamp(steering, -max, max) : 0.0;
  // The wheel turns twice the wheel angle (full lock = a quarter turn) so small corrections stay visible.
  const float turn = static_cast<float>(2.0 * value);
  const float rim = radius * 0.5f;
  const ImVec2 hub{c.x, c.y - radius * 0.14f};
  dl.AddCircle(hub, rim, kText, 40, 4.0f * s);
  for (float spoke : {0.0f, kPi, 0.5f * kPi}) dl.AddLine(hub, polar(hub, rim, spoke + turn), kText, 3.0f * s);
  dl.AddCircleFilled(polar(hub, rim, -0.5f * kPi + turn), 4.0f * s, kNeedle, 12);  // top-of-wheel mark
  char text[32];
  std::snprintf(text, sizeof text, "%+.0f°", value * 180.0 / std::numbers::pi);
  text_centered(dl, {c.x, c.y + radius * 0.62f}, text, kText, 0.75f);
  caption_below(dl, c, radius, "steering", s);
}

void draw_stick_gauge(ImDrawList& dl, ImVec2 c, float radius, const input::DriveAction& action,
                      const std::string& caption, bool held, float s) {
  dial_face(dl, c, radius, s);
  dl.AddLine({c.x - radius * 0.8f, c.y}, {c.x + radius * 0.8f, c.y}, kDialTrack, 1.0f * s);
  dl.AddLine({c.x, c.y - radius * 0.8f}, {c.x, c.y + radius * 0.8f}, kDialTrack, 1.0f * s);
  const input::JoystickView view = input::joystick_view_for_action(action, {c.x, c.y}, radius * 0.78);
  dl.AddCircle(c, static_cast<float>(view.radius), kDialTrack, 40, 2.0f * s);
  const ImVec2 knob{static_cast<float>(view.knob.x), static_cast<float>(view.knob.y)};
  dl.AddLine(c, knob, kDialTrack, 3.0f * s);
  const float knob_radius = radius * (held ? 0.3f : 0.26f);
  dl.AddCircleFilled(knob, knob_radius, held ? kNeedle : kForward, 24);
  dl.AddCircle(knob, knob_radius, kText, 24, 1.5f * s);
  // A small notch at the top of the base: pushing the knob that way drives forward.
  const float top = c.y - radius * 0.94f;
  dl.AddTriangleFilled({c.x, top}, {c.x - 5.0f * s, top + 7.0f * s}, {c.x + 5.0f * s, top + 7.0f * s}, kCaption);
  caption_below(dl, c, radius, caption.c_str(), s);
}

void draw_driving_gauges(ImDrawList& dl, const GaugeLayout& g, const DrivingGaugeValues& v, float s) {
  dl.AddRectFilled(g.min, g.max, rgba(12, 15, 20, 150), 10.0f * s);
  draw_speed_gauge(dl, g.speed, g.radius, v.speed, s);
  draw_steering_gauge(dl, g.steering, g.radius, v.steering, s);
  draw_stick_gauge(dl, g.stick, g.radius, v.stick, v.stick_caption, v.stick_held, s);
}

}  // namespace sc
