// The trainer's writing trials (see learn_write_trial_screen.hpp). As in the paper's study, the goal word is
// shown faintly underneath in every phase (the learner traces it); drills add what the paper's parking study
// had and its writing study did not: a demo where the ghost pen writes the drill first, then practice over
// the drill's ribbon. The pen clock starts at the first touch, so reading the word is free. Esc pauses a demo
// or a trace: the ghost pen stops, the pen's clock and time limit stop (CanvasPenInput leaves the paused span
// out of the trace's times) and ink is ignored until Esc again. What to play and where a finished trial goes
// is LearnTrialController's; this screen writes and draws.
#include "app/gui/screens/learn_write_trial_screen.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screens/free_write_session.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_trial_controller.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "engine/core/error.hpp"
#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/canvas_geometry.hpp"
#include "engine/writing_view/canvas_pen_input.hpp"
#include "engine/writing_view/scripted_trace.hpp"
#include "engine/writing_view/writing_scene.hpp"

namespace sc {
namespace {

constexpr double kDemoLingerSeconds = 1.0;  // the finished ghost drill stays this long before practice starts

enum class WriteStage { demo, writing, result };

bool single_stroke(const std::vector<writing::TracePoint>& path) {
  return std::all_of(path.begin() + (path.empty() ? 0 : 1), path.end(), [](const auto& p) { return p.pen; });
}

class LearnWriteTrialScreen final : public Screen {
 public:
  explicit LearnWriteTrialScreen(AppServices& services)
      : services_(services),
        flow_(services.headless ? learn_flow_for_screenshot(services, SessionPhase::Drills) : learn_flow(services)),
        trials_(flow_),
        pen_(writing::PenRecorderRules{}) {
    if (!flow_.session()) return;
    prepare(0.0);
    if (services.headless) {  // screenshots: half-way through a practice trace over the drill's ribbon
      stage_ = WriteStage::writing;
      demo_pending_ = false;
      scripted_ink_ = writing_view::scripted_learner_trace(reference_.points, {services.seed, 3.0, 4, 0.55});
    }
  }

  Color background() const override { return look_.desk; }

  void draw(UiContext& ui) override {
    if (!flow_.session()) {
      draw_no_session(ui);
      return;
    }
    const float s = ui.ui_scale;
    const float header = 56 * s, panel = std::round(340 * s), pad = std::round(20 * s);
    const PixelViewport canvas_area{pad, header + pad, static_cast<float>(ui.width) - panel - 2 * pad,
                                    static_cast<float>(ui.height) - header - 2 * pad};
    const Camera2D camera = writing_view::writing_canvas_camera(canvas_area);
    if (learn_ui::pause_pressed(ui.input) && stage_ != WriteStage::result) toggle_pause(ui);
    if (stage_ == WriteStage::demo && !paused_) advance_demo(ui.time_seconds);
    if (stage_ == WriteStage::writing && !paused_) handle_pen(ui, camera);
    draw_canvas(ui, camera);
    draw_header(ui);
    draw_panel(ui, panel, header);
    if (paused_) draw_pause(ui);
    if (stage_ == WriteStage::result) draw_result(ui);
  }

 private:
  TrainingSession& session() { return *flow_.session(); }

  // Sets up the controller's next trial.
  void prepare(double now) {
    const LearnTrialController::Trial& trial = trials_.prepare();
    reference_doc_ = trial.reference;
    reference_ = writing::parse_writing_trial(reference_doc_, trial.drill ? "drill" : "expert trial");
    is_drill_ = trial.drill;
    target_ = trial.target;
    time_limit_ = trial.time_limit;
    demo_pending_ = trial.demo_first;
    const bool on_release =
        trial.drill ? single_stroke(reference_.points) : writing::trial_ends_on_release(reference_.scenario.alphabet);
    pen_ = writing_view::CanvasPenInput({on_release, time_limit_});
    stage_started_ = now;
    paused_ = false;
    stage_ = demo_pending_ ? WriteStage::demo : WriteStage::writing;
    score_.reset();
  }

  // The two clocks stop together: the stage's (ghost pen) and the pen's (event time stamps).
  void toggle_pause(UiContext& ui) {
    paused_ = !paused_;
    if (paused_) {
      paused_at_ = ui.time_seconds;
      pen_.pause(ui.input.time_seconds);
    } else {
      stage_started_ += ui.time_seconds - paused_at_;
      pen_.resume(ui.input.time_seconds);
    }
  }

  // Seconds into the current stage, frozen while paused.
  double stage_seconds(const UiContext& ui) const { return (paused_ ? paused_at_ : ui.time_seconds) - stage_started_; }

  void draw_pause(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_write_pause", 480.0f, 0.3f);
    learn_ui::title(ui, "Paused");
    ImGui::TextWrapped(stage_ == WriteStage::demo ? "The ghost pen waits for you."
                                             : "The clock is stopped and the pen does not write.");
    ImGui::TextUnformatted("Press Esc to continue.");
    learn_ui::end_card();
  }

  void advance_demo(double now) {
    const double duration = writing_view::ghost_pen_duration(reference_.points.size());
    if (now - stage_started_ >= duration + kDemoLingerSeconds) end_demo(now);
  }

  void end_demo(double now) {
    trials_.record_demo(reference_doc_, {started_, records::utc_timestamp_now()});
    demo_pending_ = false;
    stage_ = WriteStage::writing;
    stage_started_ = now;
  }

  void handle_pen(UiContext& ui, const Camera2D& camera) {
    if (services_.headless) return;
    const FrameInput& in = ui.input;
    const bool may_press = !in.ui_wants_mouse;
    for (const MouseEvent& e : in.mouse_events) pen_.feed({e.time_seconds, e.pixels, e.left_down}, camera, may_press);
    if (in.mouse_inside || pen_.drawing())
      pen_.feed({in.time_seconds, in.mouse_pixels, in.mouse_down[0]}, camera, may_press);
    const bool enter = in.keys_pressed[SDL_SCANCODE_RETURN] || in.keys_pressed[SDL_SCANCODE_KP_ENTER];
    if (enter && !in.ui_wants_keyboard && pen_.started()) pen_.done(in.time_seconds);
    if (pen_.started() && started_.empty()) started_ = records::utc_timestamp_now();
    pen_.tick(in.time_seconds);
    if (pen_.ended()) finish(ui.time_seconds);
  }

  // Scores and keeps the finished trace; the pen is fresh for a retry.
  void finish(double now) {
    const writing::TimedTrace filled = writing::infill_trace(pen_.raw());
    writing::WritingTrial trial;
    trial.scenario = reference_.scenario;
    trial.points = filled.points;
    trial.times = filled.times;
    trial.source = "learner";
    trial.device = device_key(services_.device);
    end_reason_ = pen_.end_reason();
    score_ = writing::score_writing(reference_.points, filled.points);
    const std::string now_text = records::utc_timestamp_now();
    trials_.submit(writing::writing_trial_json(trial), {started_.empty() ? now_text : started_, now_text});
    started_.clear();
    stage_ = WriteStage::result;
    stage_started_ = now;
  }

  void draw_canvas(UiContext& ui, const Camera2D& camera) {
    writing_view::WritingScene scene;
    if (is_drill_)
      scene.ribbon = reference_.points;
    else
      scene.guide = reference_.points;
    scene.learner = services_.headless ? scripted_ink_ : pen_.raw().points;
    if (stage_ == WriteStage::demo) scene.ghost_pen = writing_view::ghost_pen_at(reference_.points, stage_seconds(ui));
    if (stage_ == WriteStage::result && score_) scene.score = *score_;
    scene.caption = reference_.scenario.word;
    ui.renderer.set_camera(camera);
    writing_view::paint_writing_scene(ui.renderer, scene, look_);
    writing_view::draw_writing_scene_text(camera, scene, ui.fonts);
  }

  void draw_header(UiContext& ui) {
    learn_ui::begin_header_bar(ui, "learn_write_header",
                               stage_ == WriteStage::result
                                   ? trials_.result_title()
                                   : learn_phase_title(session(), stage_ == WriteStage::demo || demo_pending_, false));
    if (stage_ == WriteStage::demo)
      ImGui::TextUnformatted("Watch the ghost pen: where each stroke starts, its direction, where the pen lifts.");
    else if (stage_ == WriteStage::writing)
      ImGui::Text("Time limit %.0f s from your first touch", time_limit_);
    learn_ui::end_header_bar();
  }

  void draw_panel(UiContext& ui, float width, float top) {
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.width) - width, top));
    ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(ui.height) - top));
    ImGui::Begin("learn_write_panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
    learn_ui::heading(ui, is_drill_ ? "Drill" : "Trace the word");
    if (is_drill_ && !target_.empty()) ImGui::TextWrapped("%s", target_.c_str());
    learn_ui::muted_wrapped(instructions());
    if (stage_ == WriteStage::demo) {
      if (learn_ui::primary_button(ui, "Skip the demo")) end_demo(ui.time_seconds);
    } else if (stage_ == WriteStage::writing) {
      const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
      ImGui::BeginDisabled(!pen_.started() || paused_);
      if (ImGui::Button("Done (Enter)", ImVec2(half, 0))) pen_.done(ui.input.time_seconds);
      ImGui::SameLine();
      if (ImGui::Button("Clear", ImVec2(half, 0))) pen_ = writing_view::CanvasPenInput(pen_.rules());
      ImGui::EndDisabled();
      if (pen_.started() && !pen_.ended())
        ImGui::Text("%.0f s left%s", std::ceil(pen_.seconds_left(ui.input.time_seconds)), paused_ ? " (paused)" : "");
    }
    ImGui::End();
  }

  const char* instructions() const {
    if (stage_ == WriteStage::demo) return "The ghost pen writes the drill. Then it is your turn, over the blue ribbon.";
    if (is_drill_)
      return single_stroke(reference_.points)
                 ? "Hold the button and trace the blue ribbon in one stroke. Release to finish."
                 : "Trace the blue ribbon stroke by stroke. Press Done or Enter when finished.";
    return free_write_instructions(reference_.scenario.alphabet);
  }

  void draw_result(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_write_result", 460.0f, 0.75f);
    learn_ui::title(ui, score_ && score_->score > -0.25 ? "Well written!" : "Written");
    ImGui::Text("Score %s", learn_ui::reward_text(trials_.last_reward()).c_str());
    if (score_)
      ImGui::Text("Recall %.2f  ·  precision %.2f  ·  %s", score_->recall, score_->precision,
                  trial_end_text(end_reason_));
    if (!trials_.note().empty()) learn_ui::muted_wrapped(trials_.note().c_str());
    const bool confirm = ui.time_seconds > stage_started_ && learn_ui::confirm_pressed(ui.input);
    if (trials_.draw_result_buttons(ui, confirm) == LearnTrialController::Choice::another_trial)
      prepare(ui.time_seconds);
    learn_ui::end_card();
  }

  void draw_no_session(UiContext& ui) {
    learn_ui::begin_card(ui, "learn_write_none", 520.0f);
    learn_ui::title(ui, "No session");
    if (learn_ui::primary_button(ui, "Back to the welcome page")) ui.navigator.go_to("learn_welcome");
    learn_ui::end_card();
  }

  AppServices& services_;
  LearnFlow& flow_;
  LearnTrialController trials_;
  writing_view::WritingCanvasLook look_;
  writing_view::CanvasPenInput pen_;
  Json reference_doc_;
  writing::WritingTrial reference_;  // the expert's word (tests) or the drill's stitched path
  std::vector<writing::TracePoint> scripted_ink_;
  std::optional<writing::WritingScore> score_;
  writing::TrialEnd end_reason_ = writing::TrialEnd::NotEnded;
  WriteStage stage_ = WriteStage::writing;
  double stage_started_ = 0;
  bool paused_ = false;
  double paused_at_ = 0;  // ui.time_seconds when the pause began
  double time_limit_ = 60;
  bool is_drill_ = false;
  bool demo_pending_ = false;
  std::string started_;
  std::string target_;  // the drill's target skill in plain words
};

}  // namespace

std::unique_ptr<Screen> make_learn_write_trial_screen(AppServices& services) {
  return std::make_unique<LearnWriteTrialScreen>(services);
}

}  // namespace sc
