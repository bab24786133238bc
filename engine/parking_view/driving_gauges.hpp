#pragma once
// On-screen gauges of the parking view, drawn with ImGui draw lists in framebuffer pixels: speed (a dial
// centred on 0, forward to the right in blue, reversing to the left in pink, like the ghost path), steering
// (a steering wheel turned with the front wheels and the angle in degrees) and the stick (the virtual joystick:
// base circle and knob at the position that commands the action; engine/input/virtual_joystick.hpp), used for
// the learner's live input and for the expert's inputs during demonstrations.
// Every size is a hand-picked size at 720 px multiplied by the UI scale, so the gauges are equally readable
// at 1280x720 and at 4K. Call between ImGuiLayer::begin_frame() and end_frame().
#include <imgui.h>

#include <string>

#include "engine/input/drive_action.hpp"

namespace sc {

namespace parking_view {
inline constexpr double kSpeedGaugeMax = 15.0;  // m/s at full deflection (the expert stays below ~12 m/s)
}  // namespace parking_view

struct GaugeLayout {
  float radius = 0;  // of each dial, pixels
  ImVec2 speed;      // dial centres
  ImVec2 steering;
  ImVec2 stick;
  ImVec2 min, max;  // the panel behind the three dials
};

// Three dials in a row whose panel's bottom-right corner is at `bottom_right` (pixels).
GaugeLayout layout_driving_gauges(ImVec2 bottom_right, float ui_scale);

struct DrivingGaugeValues {
  double speed = 0.0;     // m/s, negative when reversing
  double steering = 0.0;  // rad (front wheels), positive = right
  input::DriveAction stick;
  std::string stick_caption = "stick";  // e.g. "your stick", "expert's stick"
  bool stick_held = false;              // highlights the knob (the mouse is dragging it)
};

void draw_speed_gauge(ImDrawList& draw_list, ImVec2 centre, float radius, double speed, float ui_scale);
void draw_steering_gauge(ImDrawList& draw_list, ImVec2 centre, float radius, double steering, float ui_scale);
void draw_stick_gauge(ImDrawList& draw_list, ImVec2 centre, float radius, const input::DriveAction& action,
                      const std::string& caption, bool held, float ui_scale);

// The panel and all three dials at `layout`.
void draw_driving_gauges(ImDrawList& draw_list, const GaugeLayout& layout, const DrivingGaugeValues& values,
                         float ui_scale);

}  // namespace sc
