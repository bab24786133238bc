// Free drive: pick any parking scenario and drive it with the device chosen on the start screen, seeing the
// reward and success live. The car moves at the simulation's 15 Hz sub-steps (every 4th fixed 60 Hz update)
// through LiveParkingDrive, so what is shown is exactly what a recorded trial would replay.
// Esc or the gamepad's Start pauses; an unplugged gamepad pauses with a message until a pad is back.
// "Watch the expert" lets the planning expert drive the same scenario (its stick shown in the gauge); headless
// screenshots show that, on a fixed parked-lot scenario, a few steps into the manoeuvre.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/drive_input.hpp"
#include "app/gui/screens/free_drive_scenario.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking_view/driving_gauges.hpp"
#include "engine/parking_view/live_parking_drive.hpp"
#include "engine/parking_view/lot_painter.hpp"
#include "engine/parking_view/parking_scene.hpp"

namespace sc {
namespace {

constexpr int kHeadlessPreRollSteps = 8;  // control steps already driven in a screenshot
constexpr float kPanelWidth = 330.0f;     // at UI scale 1

class FreeDriveScreen final : public Screen {
 public:
  explicit FreeDriveScreen(AppServices& services) : services_(services), input_(services.device) {
    choice_.seed = services.seed;
    if (services.headless) {
      choice_.variant = LotVariant::Parked;
      expert_driving_ = show_expert_ = true;
    }
    start(choice_);
    if (services.headless)
      while (drive_->control_steps() < kHeadlessPreRollSteps && !drive_->done()) drive_->substep(expert_action());
  }

  void update(const FrameInput& frame, double dt) override {
    ticks_per_substep_ = std::max(1, static_cast<int>(std::lround(parking::kDt / dt)));
    input_.update(frame);
    if (input_.pause_toggled() && !drive_->done()) user_paused_ = !user_paused_;
    if (paused() || drive_->done()) return;
    if (++tick_ < ticks_per_substep_) return;
    tick_ = 0;
    drive_->substep(expert_driving_ ? expert_action() : input_.action());
  }

  void draw(UiContext& ui) override {
    const float s = ui.ui_scale;
    const float panel = kPanelWidth * s;
    const GaugeLayout gauges =
        layout_driving_gauges({static_cast<float>(ui.width) - 16.0f * s, static_cast<float>(ui.height) - 12.0f * s}, s);
    // The lot above the gauge strip, so the gauges never hide a parked car or the goal.
    const PixelViewport viewport{panel, 0, std::max(1.0f, static_cast<float>(ui.width) - panel),
                                 std::max(1.0f, gauges.min.y - 8.0f * s)};
    draw_scene(ui, viewport);
    draw_gauges(ui, gauges);
    draw_panel(ui, panel);
    draw_banner(ui, viewport);
  }

  Color background() const override { return Color::hex(0x14181f); }

 private:
  // -- episode ---------------------------------------------------------------------------------------------
  void start(const FreeDriveScenarioChoice& choice) {
    choice_ = choice;
    drive_ = std::make_unique<LiveParkingDrive>(make_free_drive_scenario(choice));
    tick_ = 0;
    user_paused_ = false;
    if (show_expert_ || expert_driving_) ensure_expert_plan();
  }

  void restart() { start(choice_); }

  bool paused() const { return user_paused_ || (!expert_driving_ && input_.state() != DriveInputState::ready); }

  void ensure_expert_plan() {
    if (expert_ && expert_->scenario == drive_->scenario()) return;
    const ParkingPlan plan = ParkingExpert().plan(drive_->scenario());
    expert_ = ExpertRun{drive_->scenario(), plan.actions, simulate_parking_path(drive_->scenario(), plan.actions)};
  }

  input::DriveAction expert_action() {
    ensure_expert_plan();
    const auto k = static_cast<std::size_t>(drive_->control_steps());
    if (k >= expert_->actions.size()) return {};
    return {expert_->actions[k][0], expert_->actions[k][1]};
  }

  // Fraction of the way from the previous to the current sub-step state to draw.
  double substep_alpha(double frame_alpha) const {
    if (drive_->done()) return 1.0;
    const double within = paused() ? tick_ : tick_ + frame_alpha;
    return std::clamp(within / ticks_per_substep_, 0.0, 1.0);
  }

  // -- drawing ---------------------------------------------------------------------------------------------
  void draw_scene(UiContext& ui, const PixelViewport& viewport) {
    ParkingSceneView view;
    view.layout = &drive_->layout();
    view.goal = drive_->goal();
    view.reverse_in = drive_->scenario().reverse_in;
    view.car = drive_->pose(substep_alpha(ui.alpha));
    view.trail = drive_->trail();
    if (show_expert_ && expert_) {
      view.ghost_path = &expert_->path;
      // Race the expert's ghost (not while the expert drives: it would sit exactly under the car).
      if (!expert_driving_) view.ghost_time = drive_->time_seconds();
    }
    const Camera2D camera = parking_scene_camera(view, camera_mode_, viewport);
    ui.renderer.set_camera(camera);
    paint_parking_scene(ui.renderer, view);
    if (spot_numbers_) label_spots(camera);
  }

  void draw_gauges(UiContext& ui, const GaugeLayout& layout) {
    input_.set_joystick_base({layout.stick.x, layout.stick.y}, layout.radius * 0.78f);
    DrivingGaugeValues values;
    values.speed = drive_->current().speed;
    values.steering = drive_->steering();
    if (expert_driving_) {
      values.stick = drive_->applied_action();
      values.stick_caption = "expert's stick";
    } else {
      values.stick = input_.action();
      values.stick_caption = services_.device.kind == DeviceKind::mouse_joystick ? "drag the stick" : "your stick";
      values.stick_held = input_.stick_held();
    }
    draw_driving_gauges(*ImGui::GetBackgroundDrawList(), layout, values, ui.ui_scale);
    // How to drive, left of the gauges.
    const float s = ui.ui_scale;
    ImGui::GetBackgroundDrawList()->AddText({kPanelWidth * s + 20.0f * s, layout.min.y + 16.0f * s},
                                            IM_COL32(160, 168, 184, 255), controls_hint());
  }

  void draw_panel(UiContext& ui, float width) {
    const float s = ui.ui_scale;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(ui.height)), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                   ImGuiWindowFlags_NoNav;  // arrow keys drive the car, they must not move focus
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(18.0f * s, 16.0f * s));
    ImGui::Begin("free_drive_panel", nullptr, flags);
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted("Free drive");
    ImGui::PopFont();
    draw_live_readout(ui);
    ImGui::Separator();
    draw_scenario_controls(ui);
    ImGui::Separator();
    draw_driver_controls(ui);
    ImGui::End();
    ImGui::PopStyleVar();
  }

  void draw_live_readout(UiContext& ui) {
    const float s = ui.ui_scale;
    ImGui::PushFont(ui.fonts.bold);
    if (drive_->succeeded())
      ImGui::TextColored(ImVec4(0.45f, 0.9f, 0.5f, 1), "Parked!");
    else if (drive_->collided())
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "Collision");
    else if (drive_->done())
      ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1), "Out of time");
    else if (paused())
      ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1), "Paused");
    else
      ImGui::TextUnformatted(expert_driving_ ? "The expert is driving" : "Driving");
    ImGui::PopFont();
    const double reward = drive_->live_reward();
    ImGui::Text("Step %d / %d   (%.1f s)", drive_->control_steps(), parking::kHorizon, drive_->time_seconds());
    ImGui::Text("Reward %.3f   (parked above %.2f)", reward, parking::kSuccessReward);
    // Closeness to success: 0 at reward -1 or below, full at the success threshold.
    const float closeness = static_cast<float>(std::clamp((reward + 1.0) / (1.0 + parking::kSuccessReward), 0.0, 1.0));
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram,
                          is_success_reward(reward) ? ImVec4(0.35f, 0.8f, 0.45f, 1) : ImVec4(0.18f, 0.44f, 0.85f, 1));
    ImGui::ProgressBar(closeness, ImVec2(-1, 8.0f * s), "");
    ImGui::PopStyleColor();
    ImGui::Text("Return %.2f", drive_->total_return());
  }

  void draw_scenario_controls(UiContext& ui) {
    (void)ui;
    FreeDriveScenarioChoice next = choice_;
    ImGui::TextDisabled("Scenario");
    ImGui::SetNextItemWidth(-1);
    ImGui::InputScalar("##seed", ImGuiDataType_U64, &next.seed, nullptr, nullptr, "seed %llu");
    int variant = next.variant == LotVariant::Parked ? 1 : 0;
    ImGui::RadioButton("Empty lot", &variant, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Parked cars", &variant, 1);
    next.variant = variant == 1 ? LotVariant::Parked : LotVariant::Classic;
    ImGui::Checkbox("Reverse in (nose out)", &next.reverse_in);
    const std::string current = next.goal_spot < 0 ? "goal: from the seed" : describe_spot(next.goal_spot);
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##goal", current.c_str())) {
      if (ImGui::Selectable("goal: from the seed", next.goal_spot < 0)) next.goal_spot = -1;
      for (int spot = 0; spot < parking::kSpotCount; ++spot)
        if (ImGui::Selectable(describe_spot(spot).c_str(), next.goal_spot == spot)) next.goal_spot = spot;
      ImGui::EndCombo();
    }
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    if (ImGui::Button("Restart", ImVec2(half, 0))) restart();
    ImGui::SameLine();
    if (ImGui::Button("New scenario", ImVec2(half, 0))) ++next.seed;
    if (!(next == choice_)) start(next);
  }

  void draw_driver_controls(UiContext& ui) {
    ImGui::TextDisabled("Driver");
    ImGui::TextWrapped("%s", expert_driving_ ? "The planning expert" : input_.status().c_str());
    if (ImGui::Checkbox("Watch the expert drive", &expert_driving_)) restart();
    if (ImGui::Checkbox("Show the expert's path", &show_expert_) && show_expert_) ensure_expert_plan();
    ImGui::Checkbox("Spot numbers", &spot_numbers_);
    ImGui::SameLine();
    bool follow = camera_mode_ == CameraMode::follow_car;
    ImGui::Checkbox("Follow car", &follow);
    camera_mode_ = follow ? CameraMode::follow_car : CameraMode::whole_lot;
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    if (ImGui::Button(user_paused_ ? "Resume (Esc)" : "Pause (Esc)", ImVec2(half, 0)) && !drive_->done())
      user_paused_ = !user_paused_;
    ImGui::SameLine();
    if (ImGui::Button("Back to start", ImVec2(half, 0))) ui.navigator.go_to("start");
  }

  void draw_banner(UiContext& ui, const PixelViewport& viewport) {
    std::string title, detail;
    if (!expert_driving_ && input_.state() != DriveInputState::ready) {
      title = "Paused";
      detail = input_.status() + "\nNothing is lost: the drive continues where it stopped.";
    } else if (user_paused_) {
      title = "Paused";
      detail = "Press Esc (or Start on the gamepad) to continue.";
    } else if (drive_->done()) {
      title = drive_->succeeded() ? "Parked!" : drive_->collided() ? "Collision" : "Out of time";
      detail = "Return " + format_return() + ". Restart, or try a new scenario.";
    } else {
      return;
    }
    const float s = ui.ui_scale;
    ImGui::SetNextWindowPos(ImVec2(viewport.x + viewport.width * 0.5f, viewport.height * 0.12f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.88f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoInputs;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(24.0f * s, 16.0f * s));
    ImGui::Begin("free_drive_banner", nullptr, flags);
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted(title.c_str());
    ImGui::PopFont();
    ImGui::TextUnformatted(detail.c_str());
    ImGui::End();
    ImGui::PopStyleVar();
  }

  const char* controls_hint() const {
    if (expert_driving_) return "The expert drives: watch its stick.\nEsc pauses.";
    switch (services_.device.kind) {
      case DeviceKind::gamepad:
        return "Left stick: steer, up to drive, down to brake/reverse.\nStart pauses.";
      case DeviceKind::keyboard:
        return "Arrows or WASD: up drives, down brakes/reverses.\nHold Shift to steer gently. Esc pauses.";
      case DeviceKind::mouse_joystick:
        return "Drag the stick at the right: up drives, down reverses.\nEsc pauses.";
      case DeviceKind::mouse_pen:
        break;
    }
    return "Esc pauses.";
  }

  std::string format_return() const {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", drive_->total_return());
    return text;
  }

  struct ExpertRun {
    ParkingScenario scenario;
    std::vector<ParkingAction> actions;
    ParkingPath path;
  };

  AppServices& services_;
  DriveInput input_;
  FreeDriveScenarioChoice choice_;
  std::unique_ptr<LiveParkingDrive> drive_;
  std::optional<ExpertRun> expert_;
  bool expert_driving_ = false;
  bool show_expert_ = false;
  bool spot_numbers_ = false;
  bool user_paused_ = false;
  CameraMode camera_mode_ = CameraMode::whole_lot;
  int tick_ = 0;
  int ticks_per_substep_ = 4;
};

const ScreenRegistration kFreeDriveScreenRegistration{
    {"free_drive", "Free drive: any parking scenario, any device",
     [](AppServices& services) { return std::make_unique<FreeDriveScreen>(services); }}};

}  // namespace
}  // namespace sc
