// Free writing practice ("free_write"): pick a word - generated from the run's seed or typed, classic or full
// Balinese alphabet - and write it over the faint guide with the mouse or trackpad; the score and its parts
// appear after the trial. "Show the expert" plays the ghost pen at the expert's writing speed.
// Headless runs (screenshots) have no input: a scripted hand writes the word so the image is deterministic.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/free_write_session.hpp"
#include "engine/core/error.hpp"
#include "engine/writing_view/canvas_geometry.hpp"
#include "engine/writing_view/score_badge.hpp"
#include "engine/writing_view/writing_scene.hpp"

namespace sc {
namespace {

using writing::AlphabetKind;

constexpr double kGhostLingerSeconds = 1.5;  // the finished ghost word stays this long before it fades out

bool key_pressed(const FrameInput& input, SDL_Scancode key) {
  return input.keys_pressed[static_cast<std::size_t>(key)];
}

class FreeWriteScreen final : public Screen {
 public:
  explicit FreeWriteScreen(AppServices& services) : services_(services) {
    try {
      session_.emplace(services.seed);
      if (services_.headless) session_->write_scripted({services.seed, 4.0, 4, 1.0});
    } catch (const InputError& error) {
      error_ = error.what();  // e.g. missing stroke data: say so on screen instead of crashing the app
    }
    std::snprintf(typed_.data(), typed_.size(), "%s", session_ ? session_->scenario().word.c_str() : "");
  }

  Color background() const override { return look_.desk; }

  void draw(UiContext& ui) override {
    const float panel_width = std::round(380.0f * ui.ui_scale);
    const float pad = std::round(24.0f * ui.ui_scale);
    const PixelViewport canvas_area{panel_width + pad, pad, static_cast<float>(ui.width) - panel_width - 2 * pad,
                                    static_cast<float>(ui.height) - 2 * pad};
    const Camera2D camera = writing_view::writing_canvas_camera(canvas_area);
    if (session_) {
      handle_pen(ui, camera);
      draw_canvas(ui, camera);
    }
    draw_panel(ui, panel_width);
  }

 private:
  void handle_pen(UiContext& ui, const Camera2D& camera) {
    if (services_.headless) return;
    const FrameInput& in = ui.input;
    writing_view::CanvasPenInput& pen = session_->pen();
    const bool may_press = !in.ui_wants_mouse;
    for (const MouseEvent& e : in.mouse_events) pen.feed({e.time_seconds, e.pixels, e.left_down}, camera, may_press);
    if (in.mouse_inside || pen.drawing())
      pen.feed({in.time_seconds, in.mouse_pixels, in.mouse_down[0]}, camera, may_press);
    const bool enter = key_pressed(in, SDL_SCANCODE_RETURN) || key_pressed(in, SDL_SCANCODE_KP_ENTER);
    if (enter && !in.ui_wants_keyboard && pen.started()) pen.done(in.time_seconds);
    pen.tick(in.time_seconds);
    if (pen.started()) ghost_start_.reset();  // the learner is writing: the expert steps aside
    session_->finish_if_ended();
  }

  void draw_canvas(UiContext& ui, const Camera2D& camera) {
    writing_view::WritingScene scene;
    scene.guide = session_->gold_points();
    scene.learner = session_->ink();
    if (ghost_start_) {
      const double t = ui.time_seconds - *ghost_start_;
      const double duration = writing_view::ghost_pen_duration(scene.guide.size());
      if (t <= duration + kGhostLingerSeconds)
        scene.ghost_pen = writing_view::ghost_pen_at(scene.guide, t);
      else
        ghost_start_.reset();
    }
    if (session_->result() && !session_->pen().started()) scene.score = session_->result()->score;
    scene.caption =
        session_->scenario().word + "  \xc2\xb7  " + std::string(writing::alphabet_name(session_->scenario().alphabet));
    ui.renderer.set_camera(camera);
    writing_view::paint_writing_scene(ui.renderer, scene, look_);
    writing_view::draw_writing_scene_text(camera, scene, ui.fonts);
    if (session_->pen().started() && !session_->pen().ended()) draw_timer(ui, camera);
  }

  void draw_timer(UiContext& ui, const Camera2D& camera) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f s left", std::ceil(session_->pen().seconds_left(ui.input.time_seconds)));
    const Vec2f corner = camera.world_to_pixel({492.0f, 8.0f});
    ImFont* font = ui.fonts.bold;
    const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e9f, 0.0f, text);
    ImGui::GetBackgroundDrawList()->AddText(font, font->FontSize,
                                            ImVec2(std::floor(corner.x - size.x), std::floor(corner.y)),
                                            Color::hex(0x5a6477).packed_abgr(), text);
  }

  void draw_panel(UiContext& ui, float width) {
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(ui.height)), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::Begin("free_write_panel", nullptr, flags);
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted("Free writing");
    ImGui::PopFont();
    ImGui::SameLine(ImGui::GetContentRegionMax().x - ImGui::CalcTextSize("Back").x -
                    2.0f * ImGui::GetStyle().FramePadding.x);
    if (ImGui::Button("Back")) ui.navigator.back();
    if (!session_) {
      ImGui::TextWrapped("The writing task cannot start: %s", error_.c_str());
    } else {
      draw_word_choice(ui);
      ImGui::Separator();
      draw_trial_controls(ui);
      draw_result(ui);
    }
    ImGui::End();
  }

  void draw_word_choice(UiContext& ui) {
    ImGui::PushFont(ui.fonts.bold);
    ImGui::TextUnformatted("Alphabet");
    ImGui::PopFont();
    const AlphabetKind current = session_->scenario().alphabet;
    AlphabetKind chosen = current;
    if (ImGui::RadioButton("Classic (the paper's 5)", chosen == AlphabetKind::Classic)) chosen = AlphabetKind::Classic;
    if (ImGui::RadioButton("Full Balinese (24)", chosen == AlphabetKind::Balinese)) chosen = AlphabetKind::Balinese;
    if (chosen != current) new_word(chosen);
    ImGui::TextDisabled("Symbols: %s", std::string(writing::alphabet_symbols(current)).c_str());

    ImGui::PushFont(ui.fonts.bold);
    ImGui::TextUnformatted("Word");
    ImGui::PopFont();
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Write").x - 2.0f * ImGui::GetStyle().FramePadding.x -
                            ImGui::GetStyle().ItemSpacing.x);
    const bool submitted =
        ImGui::InputText("##word", typed_.data(), typed_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Write") || submitted) {
      word_problem_ = session_->use_word(current, typed_.data());
      if (word_problem_.empty()) ghost_start_.reset();
    }
    if (!word_problem_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.48f, 0.45f, 1.0f), "%s", word_problem_.c_str());
    if (ImGui::Button("New word", ImVec2(-1, 0))) new_word(current);
  }

  void new_word(AlphabetKind kind) {
    try {
      session_->next_generated_word(kind);
      std::snprintf(typed_.data(), typed_.size(), "%s", session_->scenario().word.c_str());
      word_problem_.clear();
      ghost_start_.reset();
    } catch (const InputError& error) {
      word_problem_ = error.what();
    }
  }

  void draw_trial_controls(UiContext& ui) {
    writing_view::CanvasPenInput& pen = session_->pen();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s Time limit: %.0f s from the first touch.",
                       free_write_instructions(session_->scenario().alphabet), pen.rules().time_limit_seconds);
    ImGui::PopStyleColor();
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    ImGui::BeginDisabled(!pen.started());
    if (ImGui::Button("Done (Enter)", ImVec2(half, 0))) pen.done(ui.input.time_seconds);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!pen.started());
    if (ImGui::Button("Clear", ImVec2(half, 0))) session_->restart_trial();
    ImGui::EndDisabled();
    const bool playing = ghost_start_.has_value();
    if (ImGui::Button(playing ? "Hide the expert" : "Show the expert", ImVec2(-1, 0))) {
      if (playing)
        ghost_start_.reset();
      else
        ghost_start_ = ui.time_seconds;
    }
  }

  void draw_result(UiContext& ui) {
    const auto& result = session_->result();
    if (!result) return;
    ImGui::Separator();
    ImGui::PushFont(ui.fonts.heading);
    ImGui::TextUnformatted(writing_view::score_headline(result->score).c_str());
    ImGui::PopFont();
    ImGui::TextWrapped("Score %.3f (0 is perfect)", writing_view::rounded_score(result->score.score));
    ImGui::TextWrapped("Recall %.2f: the word you wrote", result->score.recall);
    ImGui::TextWrapped("Precision %.2f: your ink on the word", result->score.precision);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Ink %.0f of %.0f px, %.1f s, %s.", result->score.learner_ink_px, result->score.gold_ink_px,
                       result->seconds, trial_end_text(result->end));
    ImGui::PopStyleColor();
  }

  AppServices& services_;
  writing_view::WritingCanvasLook look_;
  std::optional<FreeWriteSession> session_;
  std::string error_;
  std::array<char, 16> typed_{};
  std::string word_problem_;
  std::optional<double> ghost_start_;  // screen time when "Show the expert" was pressed
};

const ScreenRegistration kFreeWriteScreenRegistration{
    {"free_write", "Free write: write a word with the mouse or trackpad",
     [](AppServices& services) { return std::make_unique<FreeWriteScreen>(services); }}};

}  // namespace
}  // namespace sc
