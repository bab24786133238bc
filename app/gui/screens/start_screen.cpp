// The start screen: pick the task and the input device, then start. "Start training" leads to the trainer
// flow ("trainer") and "Free practice" to "free_drive" / "free_write"; those screens come with later work and
// until they are registered the buttons are disabled with a clear note.
#include <imgui.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "engine/render/world_label.hpp"

namespace sc {
namespace {

constexpr const char* kTrainerScreen = "learn_welcome";

const char* practice_screen(TaskKind task) { return task == TaskKind::parking ? "free_drive" : "free_write"; }

// The devices that make sense for a task, gamepads first (in connection order).
std::vector<DeviceChoice> devices_for(TaskKind task, const std::vector<GamepadSnapshot>& gamepads) {
  std::vector<DeviceChoice> devices;
  if (task == TaskKind::writing) {
    devices.push_back({DeviceKind::mouse_pen, -1, ""});
    return devices;
  }
  for (const auto& pad : gamepads) devices.push_back({DeviceKind::gamepad, pad.instance_id, pad.name});
  devices.push_back({DeviceKind::mouse_joystick, -1, ""});
  devices.push_back({DeviceKind::keyboard, -1, ""});
  return devices;
}

bool same_device(const DeviceChoice& a, const DeviceChoice& b) {
  return a.kind == b.kind && (a.kind != DeviceKind::gamepad || a.gamepad_instance_id == b.gamepad_instance_id);
}

const char* device_hint(const DeviceChoice& device) {
  switch (device.kind) {
    case DeviceKind::gamepad:
      return "left stick steers and drives";
    case DeviceKind::mouse_joystick:
      return "drag the on-screen stick, as in the study";
    case DeviceKind::keyboard:
      return "arrow keys, Shift to steer gently";
    case DeviceKind::mouse_pen:
      return "hold the button and write";
  }
  return "";
}

class StartScreen final : public Screen {
 public:
  explicit StartScreen(AppServices& services) : services_(services) {}

  void draw(UiContext& ui) override {
    keep_device_valid(ui.input.gamepads);
    draw_backdrop(ui);
    draw_panel(ui);
  }

 private:
  void keep_device_valid(const std::vector<GamepadSnapshot>& gamepads) {
    const auto devices = devices_for(services_.task, gamepads);
    for (const auto& d : devices)
      if (same_device(d, services_.device)) return;
    services_.device = devices.front();  // e.g. the chosen gamepad was unplugged, or the task changed
  }

  // A quiet parking-lot sketch behind the panel: parked cars, a ghost path with arrows into the free spot,
  // and the learner's car, all in world metres.
  void draw_backdrop(UiContext& ui) {
    Renderer2D& r = ui.renderer;
    const float w = static_cast<float>(ui.width), h = static_cast<float>(ui.height);
    const Camera2D camera({0, 0, 32, 18}, {0, 0, w, h}, WorldYAxis::down);
    r.set_camera(camera);
    const Color line = Color::hex(0x3a4252);
    for (int i = 0; i <= 10; ++i) {
      const float x = 1.0f + 3.0f * static_cast<float>(i);
      const std::array<Vec2f, 2> top{Vec2f{x, 0.0f}, Vec2f{x, 5.5f}};
      const std::array<Vec2f, 2> bottom{Vec2f{x, 12.5f}, Vec2f{x, 18.0f}};
      r.polyline(top, Stroke::world(0.12f), line);
      r.polyline(bottom, Stroke::world(0.12f), line);
    }
    const Color parked = Color::hex(0x2a3140);
    for (int i = 0; i < 10; ++i) {
      if (i == 8) continue;  // the free spot, right of the panel
      const float x = 2.5f + 3.0f * static_cast<float>(i);
      r.fill_rect({{x, 2.9f}, {1.05f, 2.2f}, 0.0f}, parked);
      if (i != 2) r.fill_rect({{x, 15.1f}, {1.05f, 2.2f}, 0.0f}, parked);
    }
    const std::array<Vec2f, 6> ghost{Vec2f{3.0f, 9.0f},  Vec2f{12.0f, 9.0f}, Vec2f{22.0f, 9.2f},
                                     Vec2f{25.5f, 8.6f}, Vec2f{26.5f, 6.5f}, Vec2f{26.5f, 3.2f}};
    PathStyle round;
    round.join = LineJoin::round;
    r.ghost_ribbon(ghost, Stroke::world(1.6f), Color::hex(0x5b9bff, 0.16f), round);
    r.dashed_polyline(ghost, Stroke::world(0.08f), {0.6f, 0.4f}, Color::hex(0x5b9bff, 0.55f), round);
    r.arrow({8.0f, 9.0f}, {10.0f, 9.0f}, Stroke::world(0.1f), {0.5f, 0.45f}, Color::hex(0x8ab8ff, 0.7f));
    r.arrow({26.5f, 6.0f}, {26.5f, 4.4f}, Stroke::world(0.1f), {0.5f, 0.45f}, Color::hex(0x8ab8ff, 0.7f));
    r.fill_rect({{4.2f, 9.0f}, {2.2f, 1.0f}, 0.0f}, Color::hex(0x2f6fd8, 0.85f));
    r.fill_rect({{5.9f, 9.0f}, {0.35f, 0.8f}, 0.0f}, Color::hex(0x8ab8ff, 0.9f));  // windscreen: the front
    r.outline_rect({{26.5f, 2.9f}, {1.25f, 2.35f}, 0.0f}, Stroke::pixels(2.0f * ui.ui_scale),
                   Color::hex(0x5b9bff, 0.6f));
    LabelStyle label;
    label.color = Color::hex(0x8ab8ff, 0.8f);
    label.anchor = LabelAnchor::right;
    draw_world_label(camera, {27.75f, 2.9f}, "goal", label);
  }

  void draw_panel(UiContext& ui) {
    const float s = ui.ui_scale;
    const ImVec2 panel_size(620.0f * s, 0.0f);
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.width) * 0.5f, static_cast<float>(ui.height) * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(panel_size, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.96f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(36.0f * s, 30.0f * s));
    ImGui::Begin("start", nullptr, flags);
    ImGui::PushFont(ui.fonts.title);
    ImGui::TextUnformatted("SkillCoach");
    ImGui::PopFont();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Learn a motor skill with practice drills chosen for you.");
    ImGui::PopStyleColor();
    ImGui::Dummy(ImVec2(0, 8.0f * s));
    draw_task_choice(ui);
    ImGui::Dummy(ImVec2(0, 6.0f * s));
    draw_device_choice(ui);
    ImGui::Dummy(ImVec2(0, 10.0f * s));
    draw_start_buttons(ui);
    ImGui::End();
    ImGui::PopStyleVar();
  }

  void draw_task_choice(UiContext& ui) {
    const float s = ui.ui_scale;
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted("Task");
    ImGui::PopFont();
    const float gap = ImGui::GetStyle().ItemSpacing.x;
    const ImVec2 card((ImGui::GetContentRegionAvail().x - gap) * 0.5f, 64.0f * s);
    struct Option {
      TaskKind task;
      const char* label;
    };
    const Option options[] = {{TaskKind::parking, "Parking\nBack a car into a free spot"},
                              {TaskKind::writing, "Writing\nBalinese characters"}};
    // Cards are buttons: always visibly framed, the chosen one in the accent colour, left-aligned text.
    ImGui::PushStyleVar(ImGuiStyleVar_ButtonTextAlign, ImVec2(0.0f, 0.5f));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(16.0f * s, 10.0f * s));
    for (const Option& option : options) {
      if (option.task == TaskKind::writing) ImGui::SameLine();
      const bool selected = services_.task == option.task;
      const ImGuiStyle& style = ImGui::GetStyle();
      ImGui::PushStyleColor(ImGuiCol_Button,
                            selected ? style.Colors[ImGuiCol_HeaderActive] : style.Colors[ImGuiCol_FrameBg]);
      ImGui::PushStyleColor(ImGuiCol_ButtonHovered,
                            selected ? style.Colors[ImGuiCol_HeaderActive] : style.Colors[ImGuiCol_FrameBgHovered]);
      if (ImGui::Button(option.label, card)) services_.task = option.task;
      ImGui::PopStyleColor(2);
    }
    ImGui::PopStyleVar(2);
  }

  void draw_device_choice(UiContext& ui) {
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted("Input device");
    ImGui::PopFont();
    keep_device_valid(ui.input.gamepads);
    for (const DeviceChoice& device : devices_for(services_.task, ui.input.gamepads)) {
      const std::string label = describe(device) + "##" + std::to_string(static_cast<int>(device.kind)) + "_" +
                                std::to_string(device.gamepad_instance_id);
      if (ImGui::RadioButton(label.c_str(), same_device(device, services_.device))) services_.device = device;
      ImGui::SameLine();
      ImGui::TextDisabled("%s", device_hint(device));
    }
    if (services_.task == TaskKind::parking && ui.input.gamepads.empty())
      ImGui::TextDisabled("No gamepad connected - plug one in at any time.");
  }

  void draw_start_buttons(UiContext& ui) {
    const float s = ui.ui_scale;
    const bool trainer = Navigator::is_available(kTrainerScreen);
    const bool practice = Navigator::is_available(practice_screen(services_.task));
    const float gap = ImGui::GetStyle().ItemSpacing.x;
    const ImVec2 button((ImGui::GetContentRegionAvail().x - gap) * 0.5f, 48.0f * s);
    ImGui::PushFont(ui.fonts.bold);
    ImGui::BeginDisabled(!trainer);
    ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.18f, 0.44f, 0.85f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.25f, 0.52f, 0.93f, 1.0f));
    if (ImGui::Button("Start training", button)) ui.navigator.go_to(kTrainerScreen);
    ImGui::PopStyleColor(2);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!practice);
    if (ImGui::Button("Free practice", button)) ui.navigator.go_to(practice_screen(services_.task));
    ImGui::EndDisabled();
    ImGui::PopFont();
    // Instructors: the learner database's sessions, trials and diagnoses (app/gui/screens/review_screen.cpp).
    if (Navigator::is_available("review")) {
      ImGui::Dummy(ImVec2(0, 4.0f * s));
      if (ImGui::Button("Instructor review: learners, trials, diagnoses", ImVec2(-1.0f, 0.0f)))
        ui.navigator.go_to("review");
    }
    if (!trainer || !practice) {
      const char* what = !trainer && !practice ? "Training and free practice" : !trainer ? "Training" : "Free practice";
      const std::string note =
          std::string(what) + " for " + std::string(to_string(services_.task)) + " is not available yet in this build.";
      ImGui::TextDisabled("%s", note.c_str());
    }
  }

  AppServices& services_;
};

const ScreenRegistration kStartScreenRegistration{{"start", "Start: choose task and device", [](AppServices& services) {
                                                     return std::make_unique<StartScreen>(services);
                                                   }}};

}  // namespace
}  // namespace sc
