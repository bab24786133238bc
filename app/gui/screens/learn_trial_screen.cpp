// One parking trial of the trainer, whatever the phase: pre-test and evaluation (no help, countdown, time
// limit, then the score), and drills (first a demo — the ghost car drives the drill while the stick gauge
// shows the expert's inputs — then the learner practises with the ghost path and their own trail; score,
// then "one more" or "next"). What to play and where a finished trial goes is LearnTrialController's; this
// screen drives and draws. Esc / gamepad Start pauses; an unplugged gamepad pauses with a message until a device
// is back, and the trial continues where it was (nothing is lost). Writing trials have their own screen
// (learn_write_trial_screen.hpp), which this registration hands out when the task is writing.
#include <imgui.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/drive_input.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_trial_controller.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "app/gui/screens/learn_write_trial_screen.hpp"
#include "engine/core/error.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/driving_gauges.hpp"
#include "engine/parking_view/live_parking_drive.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/parking_view/parking_scene.hpp"

namespace sc {
namespace {

constexpr double kCountdownSeconds = 3.0;
constexpr int kHeadlessPreRollSteps = 8;

enum class Stage { countdown, demo, driving, result };

class LearnParkingTrialScreen final : public Screen {
 public:
  explicit LearnParkingTrialScreen(AppServices& services)
      : services_(services),
        flow_(services.headless ? learn_flow_for_screenshot(services, SessionPhase::Drills) : learn_flow(services)),
        trials_(flow_),
        input_(services.device) {
    if (!flow_.session()) return;
    prepare();
    if (services.headless) {  // screenshots: a practice run a few steps in, ghost and trail visible
      stage_ = Stage::driving;
      demo_pending_ = false;
      while (drive_->control_steps() < kHeadlessPreRollSteps && !drive_->done()) drive_->substep(expert_action());
    }
  }

  void update(const FrameInput& frame, double dt) override {
    if (!flow_.session()) return;
    ticks_per_substep_ = std::max(1, static_cast<int>(std::lround(parking::kDt / dt)));
    input_.update(frame);
    confirm_ = confirm_ || learn_ui::confirm_pressed(frame);
    if (input_.pause_toggled() && stage_ != Stage::result) paused_ = !paused_;
    if (paused()) return;
    stage_time_ += dt;
    if (stage_ == Stage::countdown && stage_time_ >= kCountdownSeconds)
      set_stage(demo_pending_ ? Stage::demo : Stage::driving);
    if (stage_ != Stage::demo && stage_ != Stage::driving) return;
    if (++tick_ < ticks_per_substep_) return;
    tick_ = 0;
    drive_->substep(stage_ == Stage::demo ? expert_action() : input_.action());
    const bool out_of_time = stage_ == Stage::driving && drive_->time_seconds() >= time_limit_;
    if (drive_->done() || out_of_time || (stage_ == Stage::demo && demo_finished())) end_run();
  }

  void draw(UiContext& ui) override {
    if (!flow_.session()) {
      learn_ui::begin_card(ui, "learn_trial_none", 520.0f);
      learn_ui::title(ui, "No session");
      if (learn_ui::primary_button(ui, "Back to the welcome page")) ui.navigator.go_to("learn_welcome");
      learn_ui::end_card();
      return;
    }
    const float s = ui.ui_scale;
    const GaugeLayout gauges =
        layout_driving_gauges({static_cast<float>(ui.width) - 16.0f * s, static_cast<float>(ui.height) - 12.0f * s}, s);
    // The lot between the header and the gauge strip, so the gauges never hide the goal (the study corner's
    // spots are the bottom-right ones) or a parked car.
    const PixelViewport viewport{0, 56 * s, static_cast<float>(ui.width),
                                 std::max(1.0f, gauges.min.y - 8.0f * s - 56 * s)};
    draw_scene(ui, viewport);
    draw_gauges(ui, gauges);
    draw_header(ui);
    if (stage_ == Stage::countdown) draw_countdown(ui);
    if (paused()) draw_pause(ui);
    if (stage_ == Stage::result) draw_result(ui);
    confirm_ = false;
  }

 private:
  TrainingSession& session() { return *flow_.session(); }

  // Sets up the run for the controller's next trial.
  void prepare() {
    const LearnTrialController::Trial& trial = trials_.prepare();
    const ParkingTrial reference = parse_parking_trial(trial.reference, trial.drill ? "drill" : "expert trial");
    scenario_ = reference.scenario;
    expert_actions_ = reference.actions;
    ghost_.reset();
    if (trial.drill) ghost_ = simulate_parking_path(reference);
    time_limit_ = trial.time_limit;
    demo_pending_ = trial.demo_first;
    drive_ = std::make_unique<LiveParkingDrive>(scenario_);
    started_ = records::utc_timestamp_now();
    set_stage(Stage::countdown);
  }

  void set_stage(Stage stage) {
    stage_ = stage;
    stage_time_ = 0;
    tick_ = 0;
    if (stage == Stage::driving && drive_->control_steps() > 0) drive_ = std::make_unique<LiveParkingDrive>(scenario_);
  }

  bool paused() const { return paused_ || (stage_ == Stage::driving && input_.state() != DriveInputState::ready); }

  input::DriveAction expert_action() const {
    const auto k = static_cast<std::size_t>(drive_->control_steps());
    if (k >= expert_actions_.size()) return {};
    return {expert_actions_[k][0], expert_actions_[k][1]};
  }
  bool demo_finished() const { return static_cast<std::size_t>(drive_->control_steps()) >= expert_actions_.size(); }

  void end_run() {
    const std::string device = device_key(services_.device);
    const Json trial = parking_trial_to_json(drive_->to_trial(stage_ == Stage::demo ? "expert" : "learner", device));
    const TrialTimes times{started_, records::utc_timestamp_now()};
    if (stage_ == Stage::demo) {
      trials_.record_demo(trial, times);
      demo_pending_ = false;
      drive_ = std::make_unique<LiveParkingDrive>(scenario_);
      set_stage(Stage::countdown);
      return;
    }
    trials_.submit(trial, times);
    set_stage(Stage::result);
  }

  void draw_scene(UiContext& ui, const PixelViewport& viewport) {
    ParkingSceneView view;
    view.layout = &drive_->layout();
    view.goal = drive_->goal();
    view.reverse_in = drive_->scenario().reverse_in;
    const double within = paused() ? tick_ : tick_ + ui.alpha;
    view.car = drive_->pose(drive_->done() ? 1.0 : std::clamp(within / ticks_per_substep_, 0.0, 1.0));
    if (stage_ != Stage::demo) view.trail = drive_->trail();
    if (ghost_) view.ghost_path = &*ghost_;
    if (ghost_ && stage_ == Stage::driving) view.ghost_time = drive_->time_seconds();
    ui.renderer.set_camera(parking_scene_camera(view, CameraMode::whole_lot, viewport));
    paint_parking_scene(ui.renderer, view);
  }

  void draw_gauges(UiContext& ui, const GaugeLayout& layout) {
    const float s = ui.ui_scale;
    input_.set_joystick_base({layout.stick.x, layout.stick.y}, layout.radius * 0.78f);
    DrivingGaugeValues values;
    values.speed = drive_->current().speed;
    values.steering = drive_->steering();
    if (stage_ == Stage::demo) {
      values.stick = drive_->applied_action();
      values.stick_caption = "expert's stick";
    } else {
      values.stick = input_.action();
      values.stick_caption = "your stick";
      values.stick_held = input_.stick_held();
    }
    draw_driving_gauges(*ImGui::GetBackgroundDrawList(), layout, values, s);
  }

  void draw_header(UiContext& ui) {
    const float s = ui.ui_scale;
    learn_ui::begin_header_bar(ui, "learn_trial_header",
                               stage_ == Stage::result
                                   ? trials_.result_title()
                                   : learn_phase_title(session(), stage_ == Stage::demo || demo_pending_, false));
    if (stage_ == Stage::driving)
      ImGui::Text("Time left %.1f s", std::max(0.0, time_limit_ - drive_->time_seconds()));
    else if (stage_ == Stage::demo)
      ImGui::TextUnformatted("Watch the ghost car: the stick at the bottom right shows the expert's inputs.");
    if (ghost_ && stage_ == Stage::driving) {
      ImGui::SameLine(0, 30 * s);
      ImGui::TextDisabled("Follow the ghost band (blue: forward, pink: reversing).%s Esc pauses.",
                          services_.device.kind == DeviceKind::keyboard ? " Shift steers gently." : "");
    }
    learn_ui::end_header_bar();
  }

  void draw_countdown(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_countdown", 360.0f, 0.3f);
    learn_ui::title(ui, demo_pending_ ? "Demo starts in" : "Get ready");
    ImGui::PushFont(ui.fonts.title);
    ImGui::Text("%d", static_cast<int>(std::ceil(kCountdownSeconds - stage_time_)));
    ImGui::PopFont();
    learn_ui::end_card();
  }

  void draw_pause(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_pause", 480.0f, 0.3f);
    learn_ui::title(ui, "Paused");
    if (input_.state() != DriveInputState::ready)
      ImGui::TextWrapped("%s", input_.status().c_str());
    else
      ImGui::TextUnformatted("Press Esc (or Start) to continue.");
    learn_ui::end_card();
  }

  void draw_result(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_result", 460.0f, 0.3f);
    learn_ui::title(ui, drive_->succeeded() ? "Parked!" : drive_->collided() ? "Bump!" : "Time is up");
    ImGui::Text("Score %s  (0 is the expert's result)", learn_ui::reward_text(trials_.last_reward()).c_str());
    if (!trials_.note().empty()) learn_ui::muted_wrapped(trials_.note().c_str());
    if (trials_.draw_result_buttons(ui, confirm_) == LearnTrialController::Choice::another_trial) prepare();
    learn_ui::end_card();
  }

  AppServices& services_;
  LearnFlow& flow_;
  LearnTrialController trials_;
  DriveInput input_;
  ParkingScenario scenario_;
  std::vector<ParkingAction> expert_actions_;
  std::optional<ParkingPath> ghost_;
  std::unique_ptr<LiveParkingDrive> drive_;
  Stage stage_ = Stage::countdown;
  double stage_time_ = 0;
  int tick_ = 0;
  int ticks_per_substep_ = 4;
  double time_limit_ = 20;
  bool paused_ = false;
  bool demo_pending_ = false;
  bool confirm_ = false;
  std::string started_;
};

const ScreenRegistration kLearnTrialScreenRegistration{{"learn_trial",
                                                        "Trainer: pre-test, drill demo and practice, evaluation trial",
                                                        [](AppServices& services) -> std::unique_ptr<Screen> {
                                                          if (services.task == TaskKind::writing)
                                                            return make_learn_write_trial_screen(services);
                                                          return std::make_unique<LearnParkingTrialScreen>(services);
                                                        }}};

}  // namespace
}  // namespace sc
