// The Review's trial viewer page: trial list, the picture with the car or pen at the playhead, playback
// controls, the legend with each skill's expert example, the input stick and the reward plot.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "app/gui/screens/learn_skill_picture.hpp"
#include "app/gui/screens/review_pages.hpp"
#include "engine/review_view/review_palette.hpp"

namespace sc {
namespace {

void draw_trial_list(UiContext& ui, ReviewModel& model, float x, float y, float w, float h) {
  // Less side padding than the other panels, so the longest label ("11. practice of drill 3  -0.21") keeps its
  // score beside the scrollbar of a long session.
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(12 * ui.ui_scale, ImGui::GetStyle().WindowPadding.y));
  begin_review_panel("review_trials", x, y, w, h, true);
  ImGui::PopStyleVar();
  ImGui::TextDisabled("Trials");
  const int current = model.trial() ? model.trial()->stored.seq : -1;
  for (const auto& t : model.session()->record().trials) {
    const std::string label = std::to_string(t.seq) + ". " +
                              review::trial_label(t).substr(0, review::trial_label(t).find(", trial")) +
                              (t.record.score ? "  " + std::to_string(*t.record.score).substr(0, 5) : "");
    if (ImGui::Selectable(label.c_str(), t.seq == current)) model.select_trial(t.seq);
  }
  ImGui::End();
}

// The learner's input at the playhead: parking (steering, throttle) on a stick; writing the pen's step.
void draw_input_stick(UiContext& ui, const review::TrialReview& trial, int step, ImVec2 centre, float radius) {
  ImDrawList& dl = *ImGui::GetWindowDrawList();
  dl.AddCircleFilled(centre, radius, IM_COL32(34, 40, 52, 255), 40);
  dl.AddCircle(centre, radius, IM_COL32(110, 120, 140, 255), 40, 2.0f * ui.ui_scale);
  dl.AddLine({centre.x - radius, centre.y}, {centre.x + radius, centre.y}, IM_COL32(70, 78, 92, 255));
  dl.AddLine({centre.x, centre.y - radius}, {centre.x, centre.y + radius}, IM_COL32(70, 78, 92, 255));
  const auto& inputs = trial.learner_track.inputs;
  if (inputs.empty()) return;
  double scale = 1.0;
  if (trial.task == TaskKind::writing) {  // pen steps in canvas pixels: scale by the trial's largest step
    scale = 1e-9;
    for (const auto& in : inputs) scale = std::max(scale, std::hypot(in[0], in[1]));
  }
  const auto& in = inputs[static_cast<std::size_t>(std::clamp(step, 0, static_cast<int>(inputs.size()) - 1))];
  // Parking: steering right, throttle up (forward); writing: the pen's direction on the canvas (y down).
  const float dx = static_cast<float>(std::clamp(in[0] / scale, -1.0, 1.0));
  const float dy =
      static_cast<float>(std::clamp((trial.task == TaskKind::parking ? -in[1] : in[1]) / scale, -1.0, 1.0));
  const ImVec2 knob(centre.x + dx * radius * 0.8f, centre.y + dy * radius * 0.8f);
  dl.AddLine(centre, knob, IM_COL32(255, 226, 138, 200), 3.0f * ui.ui_scale);
  dl.AddCircleFilled(knob, radius * 0.28f, IM_COL32(255, 226, 138, 255), 24);
}

void draw_side_panel(UiContext& ui, ReviewModel& model, float x, float y, float w, float h) {
  const float s = ui.ui_scale;
  const review::TrialReview& trial = *model.trial();
  begin_review_panel("review_legend", x, y, w, h);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::PushFont(ui.fonts.bold);
  ImGui::TextUnformatted(trial.label.c_str());
  ImGui::PopFont();
  const auto& r = trial.stored.record;
  if (r.score)
    ImGui::TextDisabled("score %.3f, %d steps, %s", *r.score, trial.learner_track.steps(), r.device.c_str());
  else
    ImGui::TextDisabled("demo (not scored), %d steps", trial.learner_track.steps());
  ImGui::TextDisabled(trial.ghost ? "Dashed: the drill's ghost path." : "Ribbon: the expert's path for this scenario.");
  ImGui::PopTextWrapPos();
  // The stick and the reward plot keep the bottom of the panel; the legend scrolls above them when a task has
  // many skills (writing has 8).
  const float radius = 38 * s, plot_h = 136 * s;
  const float bottom_h =
      ImGui::GetFontSize() * 1.6f + 2 * radius + plot_h + 4 * ImGui::GetStyle().ItemSpacing.y + 24 * s;
  const float legend_h = std::max(60 * s, ImGui::GetWindowPos().y + h - ImGui::GetCursorScreenPos().y - bottom_h);
  ImGui::BeginChild("legend", {0, legend_h}, false);
  // One row per skill in the picture: its colour, its words and the expert example the trainer shows.
  std::set<int> skills;
  for (const auto* spans : {&trial.learner_skills, &trial.expert_skills, &trial.ghost_skills})
    for (const auto& span : *spans) skills.insert(span.skill);
  const ImVec2 thumb(84 * s, 50 * s);
  for (int skill : skills) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList& dl = *ImGui::GetWindowDrawList();
    const std::string words = model.session()->kit().describe_skill(skill);
    if (const SkillPictureData* picture = model.skill_picture(skill)) {
      const auto draw = [picture](ImDrawList& d, ImVec2 top_left, ImVec2 size) {
        draw_skill_picture(d, top_left, size, *picture, false);
      };
      draw(dl, at, thumb);
      ImGui::Dummy(thumb);
      enlarge_on_hover("How the expert does \"" + words + "\": the coloured part, ending at the dot", thumb, draw);
      ImGui::SetCursorScreenPos(at);
    }
    dl.AddRectFilled({at.x + thumb.x + 8 * s, at.y + 4 * s}, {at.x + thumb.x + 22 * s, at.y + 18 * s},
                     model.palette().color_u32(skill), 3.0f);
    ImGui::SetCursorScreenPos({at.x + thumb.x + 28 * s, at.y});
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("%d  %s", skill, words.c_str());
    ImGui::PopTextWrapPos();
    ImGui::SetCursorScreenPos({at.x, at.y + thumb.y + 6 * s});
  }
  ImGui::EndChild();
  ImGui::TextDisabled(trial.task == TaskKind::parking ? "Stick: steering / throttle" : "Pen direction");
  const ImVec2 c = ImGui::GetCursorScreenPos();
  draw_input_stick(ui, trial, model.playback().current_step(), {c.x + radius + 4 * s, c.y + radius + 4 * s}, radius);
  ImGui::Dummy({2 * radius + 8 * s, 2 * radius + 8 * s});
  review_view::RewardPlot plot = reward_plot(trial);
  plot.playhead = model.playback().seconds();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  review_view::draw_reward_plot(*ImGui::GetWindowDrawList(), at, {w - 2 * ImGui::GetStyle().WindowPadding.x, plot_h},
                                plot, s);
  ImGui::Dummy({0, plot_h});
  ImGui::End();
}

void draw_playback(UiContext& ui, ReviewModel& model, float x, float y, float w, float h) {
  const float s = ui.ui_scale;
  review::Playback& p = model.playback();
  begin_review_panel("review_playback", x, y, w, h);
  if (ImGui::Button(p.playing() ? "Pause" : "Play", {90 * s, 0})) p.toggle();
  ImGui::SameLine();
  float position = static_cast<float>(p.position());
  ImGui::SetNextItemWidth(w - 330 * s);  // room for Play, "speed" and the speed menu
  char label[48];
  std::snprintf(label, sizeof label, "%.1f s", p.seconds());
  if (ImGui::SliderFloat("##scrub", &position, 0.0f, static_cast<float>(p.steps()), label)) p.scrub(position);
  ImGui::SameLine();
  ImGui::TextDisabled("speed");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(100 * s);
  char current[16];
  std::snprintf(current, sizeof current, "%gx", p.speed());
  if (ImGui::BeginCombo("##speed", current)) {
    for (double speed : review::kPlaybackSpeeds) {
      char text[16];
      std::snprintf(text, sizeof text, "%gx", speed);
      if (ImGui::Selectable(text, std::abs(p.speed() - speed) < 1e-9)) p.set_speed(speed);
    }
    ImGui::EndCombo();
  }
  ImGui::End();
}

}  // namespace

void draw_review_trial(UiContext& ui, ReviewModel& model) {
  if (!model.session() || !model.trial()) return;
  const float s = ui.ui_scale, top = kReviewTopBar * s;
  const float list_w = 250 * s, side_w = 340 * s, bar_h = 52 * s;
  const float W = static_cast<float>(ui.width), H = static_cast<float>(ui.height);
  draw_trial_list(ui, model, 0, top, list_w, H - top);
  const PixelViewport viewport{list_w, top, W - list_w - side_w, H - top - bar_h};
  review_view::TrialPicture& picture = model.picture();
  picture.playhead = model.playback().position();
  ui.renderer.set_camera(review_view::trial_picture_camera(picture, viewport));
  review_view::paint_trial_picture(ui.renderer, picture);
  draw_playback(ui, model, list_w, H - bar_h, viewport.width, bar_h);
  draw_side_panel(ui, model, W - side_w, top, side_w, H - top);
}

}  // namespace sc
