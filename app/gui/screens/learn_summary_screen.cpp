// The end of a round: pre-test vs final-test score, the improvement, how each skill changed, and a
// before/after picture (the learner's first pre-test path and last final-test path over the expert's), with
// "another adaptive round" (Adaptive) or "finish".
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_skill_picture.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "engine/core/error.hpp"

namespace sc {
namespace {

// The change's word in a colour that says whether it is good news: green better, red worse, grey otherwise.
void draw_change_word(const SkillChange& change) {
  const SkillTrend trend = skill_trend(change);
  const ImVec4 colour = trend == SkillTrend::better  ? ImVec4(0.5f, 0.9f, 0.5f, 1)
                        : trend == SkillTrend::worse ? ImVec4(1.0f, 0.6f, 0.5f, 1)
                                                     : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
  ImGui::TextColored(colour, "%s", to_string(trend));
}

class LearnSummaryScreen final : public Screen {
 public:
  explicit LearnSummaryScreen(AppServices& services)
      : flow_(services.headless ? learn_flow_for_screenshot(services, SessionPhase::Summary) : learn_flow(services)) {
    if (flow_.session() && flow_.session()->phase() == SessionPhase::Summary) summary_ = flow_.session()->summary();
  }

  void update(const FrameInput& input, double) override { confirm_ = confirm_ || learn_ui::confirm_pressed(input); }

  void draw(UiContext& ui) override {
    TrainingSession* s = flow_.session();
    if (!s || !summary_) {
      ui.navigator.go_to("learn_welcome");
      return;
    }
    const float sc = ui.ui_scale;
    learn_ui::begin_card(ui, "learn_summary", 900.0f);
    learn_ui::title(ui, "Your progress");
    ImGui::Text("Pre-test score %s   ->   final test %s", learn_ui::reward_text(summary_->pretest_mean).c_str(),
                learn_ui::reward_text(summary_->eval_mean).c_str());
    ImGui::PushFont(ui.fonts.bold);
    ImGui::Text("%s by %.3f (0 is the expert's result)", summary_->improvement >= 0 ? "Improved" : "Dropped",
                std::abs(summary_->improvement));
    ImGui::PopFont();
    ImGui::TextDisabled("Round %d, %d practice trial%s.", summary_->round, summary_->practice_trials,
                        summary_->practice_trials == 1 ? "" : "s");
    ImGui::Dummy(ImVec2(0, 6 * sc));
    draw_before_after(ui, *s);
    ImGui::Dummy(ImVec2(0, 6 * sc));
    learn_ui::heading(ui, "Skills (mistake weight before -> after; 0 = none)");
    // The table scrolls when the window is too short for every row (the parking model has 16 skills), so
    // the two buttons below always show.
    int rows = 0;
    for (const SkillChange& c : summary_->skills) rows += c.seen || c.drilled ? 1 : 0;
    const float row = ImGui::GetTextLineHeight() + ImGui::GetStyle().CellPadding.y * 2;  // a table row's pitch
    const float rows_height = rows * row;
    // Whole rows only, so the last visible one is not cut.
    const float room =
        row * std::max(3.0f, std::floor((static_cast<float>(ui.height) - ImGui::GetCursorPosY() - 160 * sc) / row));
    const ImGuiTableFlags scroll = rows_height > room ? ImGuiTableFlags_ScrollY : 0;
    if (ImGui::BeginTable("skills", 3, ImGuiTableFlags_SizingStretchProp | scroll, ImVec2(0, scroll ? room : 0))) {
      // The figures and the word keep their whole width beside a scrollbar; the skill's words take the rest.
      const float gap = 12 * sc;
      ImGui::TableSetupColumn("skill", ImGuiTableColumnFlags_WidthStretch);
      ImGui::TableSetupColumn("E", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("-0.00 -> -0.00").x + gap);
      ImGui::TableSetupColumn("trend", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("no mistake").x + gap);
      for (const SkillChange& c : summary_->skills) {
        if (!c.seen && !c.drilled) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (c.drilled)
          ImGui::Text("%s  (drilled, %d trial%s)", s->kit().describe_skill(c.skill).c_str(), c.practice_trials,
                      c.practice_trials == 1 ? "" : "s");
        else
          ImGui::TextUnformatted(s->kit().describe_skill(c.skill).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%.2f -> %.2f", c.before, c.after);
        ImGui::TableNextColumn();
        draw_change_word(c);
      }
      ImGui::EndTable();
    }
    ImGui::Dummy(ImVec2(0, 6 * sc));
    if (s->can_continue() && (learn_ui::primary_button(ui, "Another adaptive round") || confirm_)) {
      try {
        s->start_next_round();
        ui.navigator.go_to(screen_for_phase(s->phase()));
      } catch (const InputError& e) {
        flow_.message = e.what();
      }
    }
    if (ImGui::Button("Finish", ImVec2(-1, 40 * sc))) {
      s->finish();
      ui.navigator.go_to("start");
    }
    confirm_ = false;
    learn_ui::end_card();
  }

 private:
  // The first pre-test trial and the first final-test trial, each as the whole path, side by side.
  void draw_before_after(UiContext& ui, TrainingSession& s) {
    const float sc = ui.ui_scale;
    const ImVec2 size(380 * sc, 150 * sc);
    ImDrawList& d = *ImGui::GetWindowDrawList();
    const auto picture = [&](const char* caption, const Json& trial, const Json& expert) {
      ImGui::BeginGroup();
      ImGui::TextDisabled("%s", caption);
      const ImVec2 at = ImGui::GetCursorScreenPos();
      draw_overlay_picture(d, at, size, trial, expert);
      ImGui::Dummy(size);
      ImGui::EndGroup();
    };
    if (s.pretest_trials().empty() || s.eval_trials(s.round()).empty()) return;
    const auto& pool = s.kit().expert_pool();
    picture("Before (yellow: you, blue: the expert)", s.pretest_trials().front(),
            pool[static_cast<std::size_t>(s.pretest_pool_indices().front())].trial);
    ImGui::SameLine(0, 20 * sc);
    picture("After: your first final-test trial", s.eval_trials(s.round()).front(), s.eval_experts().front().trial);
  }

  LearnFlow& flow_;
  std::optional<RoundSummary> summary_;
  bool confirm_ = false;
};

const ScreenRegistration kLearnSummaryScreenRegistration{
    {"learn_summary", "Trainer: round summary, before/after, another round",
     [](AppServices& services) { return std::make_unique<LearnSummaryScreen>(services); }}};

}  // namespace
}  // namespace sc
