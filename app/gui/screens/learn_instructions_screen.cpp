// The illustrated instructions page before the pre-test: what the goal is, the controls of the chosen device
// (a picture of it) and what the ghost path means (a picture of a ghost ribbon with a learner's trail).
#include <imgui.h>

#include <cmath>
#include <memory>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_ui.hpp"

namespace sc {
namespace {

constexpr ImU32 kInk = IM_COL32(230, 234, 242, 255);
constexpr ImU32 kMuted = IM_COL32(120, 130, 150, 255);
constexpr ImU32 kAccent = IM_COL32(91, 155, 255, 255);
constexpr ImU32 kGhost = IM_COL32(91, 155, 255, 70);
constexpr ImU32 kTrail = IM_COL32(255, 226, 138, 230);

// A key `width` wide and `size` high (a square key when width is 0).
void key_cap(ImDrawList& d, ImVec2 at, float size, const char* label, bool lit, float width = 0.0f) {
  const float w = width > 0.0f ? width : size;
  d.AddRectFilled(at, ImVec2(at.x + w, at.y + size), lit ? kAccent : IM_COL32(50, 58, 74, 255), size * 0.15f);
  const ImVec2 t = ImGui::CalcTextSize(label);
  d.AddText(ImVec2(at.x + (w - t.x) * 0.5f, at.y + (size - t.y) * 0.5f), kInk, label);
}

// The device in a box of w x h pixels at `o`.
void draw_device(ImDrawList& d, ImVec2 o, float w, float h, DeviceKind kind) {
  const ImVec2 c(o.x + w * 0.5f, o.y + h * 0.5f);
  switch (kind) {
    case DeviceKind::keyboard: {
      const float k = h * 0.3f, g = k * 0.12f, x = c.x + k * 1.2f;  // the arrows right of Shift, all centred
      key_cap(d, ImVec2(x - k * 0.5f, c.y - k - g), k, "^", true);
      key_cap(d, ImVec2(x - k * 1.5f - g, c.y), k, "<", true);
      key_cap(d, ImVec2(x - k * 0.5f, c.y), k, "v", true);
      key_cap(d, ImVec2(x + k * 0.5f + g, c.y), k, ">", true);
      key_cap(d, ImVec2(x - k * 3.9f - g, c.y), k, "Shift", false, k * 2.1f);  // held: gentle steering
      break;
    }
    case DeviceKind::gamepad: {
      d.AddRectFilled(ImVec2(c.x - w * 0.32f, c.y - h * 0.22f), ImVec2(c.x + w * 0.32f, c.y + h * 0.25f),
                      IM_COL32(50, 58, 74, 255), h * 0.2f);
      d.AddCircleFilled(ImVec2(c.x - w * 0.15f, c.y), h * 0.11f, kAccent);  // the left stick drives
      d.AddCircleFilled(ImVec2(c.x + w * 0.15f, c.y), h * 0.05f, kMuted);
      d.AddCircleFilled(ImVec2(c.x + w * 0.22f, c.y - h * 0.07f), h * 0.04f, kMuted);
      break;
    }
    case DeviceKind::mouse_joystick: {
      d.AddCircle(c, h * 0.34f, kMuted, 48, 2.0f);
      d.AddCircleFilled(ImVec2(c.x + h * 0.12f, c.y - h * 0.14f), h * 0.1f, kAccent);
      d.AddLine(c, ImVec2(c.x + h * 0.12f, c.y - h * 0.14f), kAccent, 2.0f);
      break;
    }
    case DeviceKind::mouse_pen: {
      d.AddRectFilled(ImVec2(c.x - h * 0.16f, c.y - h * 0.3f), ImVec2(c.x + h * 0.16f, c.y + h * 0.3f),
                      IM_COL32(50, 58, 74, 255), h * 0.16f);
      d.AddRectFilled(ImVec2(c.x - h * 0.16f, c.y - h * 0.3f), ImVec2(c.x, c.y - h * 0.05f), kAccent, h * 0.1f);
      break;
    }
  }
}

// A ghost ribbon (the expert's path) and a learner's trail that follows it a little off.
void draw_ghost(ImDrawList& d, ImVec2 o, float w, float h, bool parking) {
  std::vector<ImVec2> ghost, trail;
  for (int i = 0; i <= 40; ++i) {
    const float t = static_cast<float>(i) / 40.0f;
    const float y = parking ? (t < 0.6f ? 0.55f : 0.55f - (t - 0.6f) * 1.1f) : 0.5f + 0.25f * std::sin(t * 6.28f);
    ghost.emplace_back(o.x + w * (0.08f + 0.84f * t), o.y + h * y);
    if (t < 0.75f) trail.emplace_back(o.x + w * (0.08f + 0.84f * t), o.y + h * (y + 0.06f * std::sin(t * 9.0f)));
  }
  d.AddPolyline(ghost.data(), static_cast<int>(ghost.size()), kGhost, ImDrawFlags_None, h * 0.16f);
  d.AddPolyline(trail.data(), static_cast<int>(trail.size()), kTrail, ImDrawFlags_None, 3.0f);
  d.AddCircleFilled(trail.back(), 6.0f, kTrail);
}

const char* device_words(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::keyboard:
      return "Up drives forward, Down reverses, Left and Right steer; hold Shift to steer gently.";
    case DeviceKind::gamepad:
      return "The left stick: up/down for throttle and reverse, left/right to steer.";
    case DeviceKind::mouse_joystick:
      return "Drag the on-screen stick with the mouse: up/down throttle, left/right steer.";
    case DeviceKind::mouse_pen:
      return "Hold the left button to put the pen down; release it when the word is done.";
  }
  return "";
}

class LearnInstructionsScreen final : public Screen {
 public:
  explicit LearnInstructionsScreen(AppServices& services)
      : services_(services),
        flow_(services.headless ? learn_flow_for_screenshot(services, SessionPhase::Pretest) : learn_flow(services)) {}

  void update(const FrameInput& input, double) override { confirm_ = confirm_ || learn_ui::confirm_pressed(input); }

  void draw(UiContext& ui) override {
    const float s = ui.ui_scale;
    const bool parking = services_.task == TaskKind::parking;
    learn_ui::begin_card(ui, "learn_instructions", 820.0f);
    learn_ui::title(ui, "How it works");
    ImGui::TextWrapped("%s", parking
                                 ? "Goal: drive the blue car into the marked spot, facing the way the outline shows, "
                                   "without touching the walls or the parked cars. Each trial has a time limit."
                                 : "Goal: write the shown Balinese characters over the guide, in the right stroke "
                                   "order and direction. Each trial has a time limit.");
    draw_lot_note();
    ImGui::Dummy(ImVec2(0, 6 * s));
    const float box_w = 360.0f * s, box_h = 150.0f * s;
    ImDrawList& d = *ImGui::GetWindowDrawList();
    ImGui::BeginGroup();
    learn_ui::heading(ui, "Your controls");
    ImVec2 at = ImGui::GetCursorScreenPos();
    d.AddRectFilled(at, ImVec2(at.x + box_w, at.y + box_h), IM_COL32(28, 33, 43, 255), 8 * s);
    draw_device(d, at, box_w, box_h, services_.device.kind);
    ImGui::Dummy(ImVec2(box_w, box_h));
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + box_w);
    ImGui::TextWrapped("%s", device_words(services_.device.kind));
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::SameLine(0, 24 * s);
    ImGui::BeginGroup();
    learn_ui::heading(ui, "The ghost path");
    at = ImGui::GetCursorScreenPos();
    d.AddRectFilled(at, ImVec2(at.x + box_w, at.y + box_h), IM_COL32(28, 33, 43, 255), 8 * s);
    draw_ghost(d, at, box_w, box_h, parking);
    ImGui::Dummy(ImVec2(box_w, box_h));
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + box_w);
    ImGui::TextWrapped(
        "In practice drills, the blue band is the expert's path: follow it. Your own trail is drawn "
        "in yellow. First the ghost shows the drill, then it is your turn.");
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::Dummy(ImVec2(0, 8 * s));
    // A writing trial's clock starts at the pen's first touch, so reading is never timed; Esc pauses both tasks.
    learn_ui::muted_wrapped(parking ? "The pre-test comes first: a few trials without help, so SkillCoach can see "
                                      "which skills to practise. Esc pauses at any time."
                                    : "The pre-test comes first: a few trials without help, so SkillCoach can see "
                                      "which skills to practise. Each trial's clock starts when the pen first "
                                      "touches, so take your time to read the word. Esc pauses.");
    ImGui::Dummy(ImVec2(0, 6 * s));
    if (learn_ui::primary_button(ui, "Start the pre-test") || confirm_) ui.navigator.go_to("learn_trial");
    confirm_ = false;
    learn_ui::end_card();
  }

 private:
  // Parking: which spots this session's goals use, so a learner is not surprised by the corner-only goals.
  void draw_lot_note() {
    const TrainingSession* session = flow_.session();
    if (!session || !session->settings().goal_region) return;
    learn_ui::muted_wrapped(*session->settings().goal_region == GoalRegion::StudyCorner
                                ? "This session's goals are the three spots at the bottom right of the lot, where "
                                  "fewer manoeuvres are needed. Later sessions use the whole lot."
                                : "Goals can be any spot of the lot.");
  }

  AppServices& services_;
  LearnFlow& flow_;
  bool confirm_ = false;
};

const ScreenRegistration kLearnInstructionsScreenRegistration{
    {"learn_instructions", "Trainer: illustrated instructions",
     [](AppServices& services) { return std::make_unique<LearnInstructionsScreen>(services); }}};

}  // namespace
}  // namespace sc
