// Analysis and diagnosis: a progress note while the pre-test (or the last round's practice) is segmented and
// Alg. 2 runs (a fraction of a second), then one bar per skill the expert used — longer = more mistakes —
// each with a small picture of the skill's expert segment, a picture of where it went wrong (the learner's pre-test
// trial, the part aligned with that segment in orange), the kit's plain words and why it lost expertise (its
// largest penalty: the trial it was missing in or done badly in); the skills the drills will target are highlighted.
#include <imgui.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/learn_diagnosis_pictures.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_hand_picture.hpp"
#include "app/gui/screens/learn_skill_picture.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "engine/core/error.hpp"
#include "teaching/curricula/teachable_skills.hpp"
#include "teaching/sessions/session_analysis.hpp"
#include "teaching/tasks/expert_demos.hpp"

namespace sc {
namespace {

// Why a skill lost expertise and where: its largest penalty, e.g. "missing in trial 2" (Alg. 2 charges a
// skill the expert used in a trial that the learner's trial does not show), "done with a large error in
// trial 2" (quality-aware expertise: shown, but done clearly worse than the learner's other skills) or "done a
// little wrong every time, most in trial 2" (repeated evidence: no one segment far off, every one off).
std::string why_words(const ExpertiseEstimate& e, int skill) {
  const auto& list = e.contributions[static_cast<std::size_t>(skill)];
  const ExpertiseContribution* worst = nullptr;
  int penalties = 0;
  for (const ExpertiseContribution& c : list) {
    if (c.delta <= 0.0) continue;
    ++penalties;
    if (!worst || c.delta > worst->delta) worst = &c;
  }
  if (!worst) return "";
  if (worst->repeated) return "done a little wrong every time, most in trial " + std::to_string(worst->trial + 1);
  std::string out = std::string(worst->execution ? "done with a large error in trial " : "missing in trial ") +
                    std::to_string(worst->trial + 1);
  if (penalties > 1) out += " (and " + std::to_string(penalties - 1) + " more)";
  return out;
}

// One row's text: the kit's words with the row's tag, and why the skill is ranked where it is.
struct SkillRowText {
  std::string title;
  std::string status;
  bool drilled = false;
};

std::vector<SkillRowText> skill_rows(const TrainingSession& s, int shown, bool any_penalty) {
  const ExpertiseEstimate& e = s.diagnosis();
  // A weak skill too brief to practise on its own (teachable_skills.hpp) says so: otherwise a learner
  // wonders why a long bar gets no drill.
  const std::vector<Segmentation> pool = demo_skills(s.kit().expert_pool());
  const int min_steps = s.curriculum_config().min_skill_steps;
  std::vector<SkillRowText> rows;
  for (int r = 0; r < shown; ++r) {
    const int m = e.ranking[static_cast<std::size_t>(r)];
    SkillRowText row;
    row.drilled = std::any_of(s.curriculum().items.begin(), s.curriculum().items.end(), [m](const auto& it) {
      return std::find(it.target_skills.begin(), it.target_skills.end(), m) != it.target_skills.end();
    });
    const bool brief = !row.drilled && !is_teachable(m, pool, min_steps);
    // No-break spaces keep a tag whole when a long name wraps.
    row.title = s.kit().describe_skill(m) + (row.drilled ? "   -\u00a0drills\u00a0now"
                                             : brief     ? "   -\u00a0too\u00a0brief\u00a0to\u00a0drill\u00a0alone"
                                                         : "");
    // A target with no penalty, when others have one, was ranked among equals by how much the expert uses it: say
    // so, or a learner wonders why a skill with no mistake gets a drill.
    row.status = why_words(e, m);
    if (row.status.empty())
      row.status = std::string(target_reason_words(TargetReason::NoMistake)) +
                   (row.drilled && any_penalty ? ": one the expert uses most" : "");
    rows.push_back(std::move(row));
  }
  return rows;
}

// Where the reasons go, for the whole page at once: beside every skill's words when each fits on one line with
// them, else on a line of their own in every row. Deciding per row made rows of one list look unlike each other.
struct RowLayout {
  bool status_beside = false;
  float height = 0.0f;  // of all rows, for the list's child window
};

RowLayout row_layout(const std::vector<SkillRowText>& rows, float column, float picture_height, float bar_height,
                     float beside_gap, float line_gap) {
  RowLayout out;
  out.status_beside = std::all_of(rows.begin(), rows.end(), [&](const SkillRowText& r) {
    return ImGui::CalcTextSize(r.title.c_str()).x + beside_gap + ImGui::CalcTextSize(r.status.c_str()).x <= column;
  });
  for (const SkillRowText& r : rows) {
    float text = ImGui::CalcTextSize(r.title.c_str(), nullptr, false, column).y + line_gap + bar_height;
    if (!out.status_beside) text += ImGui::GetTextLineHeight() + line_gap;
    out.height += std::max(picture_height, text) + ImGui::GetStyle().ItemSpacing.y;
  }
  return out;
}

class LearnDiagnosisScreen final : public Screen {
 public:
  explicit LearnDiagnosisScreen(AppServices& services)
      : services_(services),
        flow_(services.headless ? learn_flow_for_screenshot(services, SessionPhase::Drills) : learn_flow(services)) {}

  void update(const FrameInput& input, double) override {
    confirm_ = confirm_ || learn_ui::confirm_pressed(input);
    TrainingSession* s = flow_.session();
    // The progress note is drawn first; the analysis runs on the next update.
    if (s && s->phase() == SessionPhase::Diagnosis && ++frames_ > 1) {
      try {
        s->analyse();
      } catch (const InputError& e) {
        flow_.message = e.what();
      }
    }
  }

  void draw(UiContext& ui) override {
    TrainingSession* s = flow_.session();
    if (!s) {
      ui.navigator.go_to("learn_welcome");
      return;
    }
    if (s->phase() == SessionPhase::Diagnosis) {
      learn_ui::begin_card(ui, "learn_analysis", 520.0f);
      learn_ui::title(ui, "Analysing your trials...");
      ImGui::ProgressBar(frames_ > 1 ? 0.9f : 0.3f, ImVec2(-1, 0), "");
      if (!flow_.message.empty()) ImGui::TextWrapped("%s", flow_.message.c_str());
      learn_ui::end_card();
      return;
    }
    draw_diagnosis(ui, *s);
  }

 private:
  void draw_diagnosis(UiContext& ui, TrainingSession& s) {
    const float sc = ui.ui_scale;
    const ExpertiseEstimate& e = s.diagnosis();
    const TaskKit& kit = s.kit();
    learn_ui::begin_card(ui, "learn_diagnosis", 900.0f);
    learn_ui::title(ui, s.round() == 1 ? "What the pre-test showed" : "Where you stand now");
    learn_ui::muted_wrapped(
        "Each bar is one skill the expert uses; a longer bar means more trouble with it. The "
        "highlighted skills get drills now.");
    if (!kit.extractor_notice().empty()) learn_ui::muted_wrapped(("Note: " + kit.extractor_notice()).c_str());
    const float hand_height = draw_learner_hand(ui, s);
    double worst = 1e-9;
    for (double v : e.expertise) worst = std::max(worst, -v);
    if (worst <= 1e-9)
      learn_ui::muted_wrapped(kit.learners_expertise() == ExpertiseMode::QualityAware
                                  ? "No skill stood out as missing or done badly: the drills cover the skills the "
                                    "expert relies on most."
                                  : "No skill stood out as missing: the drills cover the skills the expert relies on "
                                    "most.");
    const int shown = std::min<int>(static_cast<int>(e.ranking.size()), 8);
    // Where each target went wrong, when the diagnosis shown is the pre-test's (later adaptive rounds' evidence is
    // practice).
    const PlacedDiagnosis* placed = s.pretest_places();
    if (placed && placed->expertise.estimate.expertise != e.expertise) placed = nullptr;
    const bool places = placed && std::any_of(e.ranking.begin(), e.ranking.begin() + shown,
                                              [placed](int m) { return charged_why(*placed, m) != nullptr; });
    const char* hint = places ? "Left: the skill as the expert does it. Right: the pre-test trial it went wrong in, "
                                "that part in orange. Point at a picture to see it larger."
                              : "Point at a picture to see it larger.";
    const float hint_height =
        ImGui::CalcTextSize(hint, nullptr, false, ImGui::GetContentRegionAvail().x).y + ImGui::GetStyle().ItemSpacing.y;
    learn_ui::muted_wrapped(hint);
    const std::vector<SkillRowText> rows = skill_rows(s, shown, worst > 1e-9);
    const ImVec2 pic(110 * sc, 56 * sc);
    const float gap = 14 * sc, bar_height = 18 * sc;
    // The text column: what is left beside the pictures, less a scroll bar's width in case the list scrolls.
    const float pictures = places ? 2 * pic.x + 6 * sc : pic.x;
    const float column = ImGui::GetContentRegionAvail().x - pictures - gap - ImGui::GetStyle().ScrollbarSize;
    // A row's lines sit closer together than the rows do, so each skill reads as one block.
    const float line_gap = 3 * sc;
    const RowLayout layout = row_layout(rows, column, pic.y, bar_height, 10 * sc, line_gap);
    // The list scrolls when the window is too short for every row, so the button below always shows.
    const float room = std::max(2 * pic.y, static_cast<float>(ui.height) - 330 * sc - hand_height - hint_height);
    ImGui::BeginChild("skill_rows", ImVec2(0, std::min(layout.height, room)), false,
                      layout.height <= room ? ImGuiWindowFlags_NoScrollbar : 0);
    ImDrawList& d = *ImGui::GetWindowDrawList();
    for (int r = 0; r < shown; ++r) {
      const int m = e.ranking[static_cast<std::size_t>(r)];
      const SkillRowText& row = rows[static_cast<std::size_t>(r)];
      pictures_.draw_row(d, pic, s, places ? placed : nullptr, m, row.drilled, sc);
      ImGui::SameLine(0, gap);
      ImGui::BeginGroup();
      ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, line_gap));
      if (row.drilled) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.4f, 1.0f));
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + column);
      ImGui::TextWrapped("%s", row.title.c_str());
      ImGui::PopTextWrapPos();
      if (row.drilled) ImGui::PopStyleColor();
      if (layout.status_beside) ImGui::SameLine(0, 10 * sc);
      ImGui::TextDisabled("%s", row.status.c_str());
      const float fraction = static_cast<float>(-e.expertise[static_cast<std::size_t>(m)] / worst);
      ImGui::PushStyleColor(ImGuiCol_PlotHistogram,
                            row.drilled ? ImVec4(1.0f, 0.6f, 0.3f, 1.0f) : ImVec4(0.36f, 0.6f, 1.0f, 1.0f));
      char overlay[32];
      std::snprintf(overlay, sizeof overlay, "%.2f", e.expertise[static_cast<std::size_t>(m)]);
      ImGui::ProgressBar(std::max(0.02f, fraction), ImVec2(column, bar_height), overlay);
      ImGui::PopStyleColor();
      ImGui::PopStyleVar();
      ImGui::EndGroup();
    }
    ImGui::EndChild();
    ImGui::Dummy(ImVec2(0, 6 * sc));
    const int trials = s.practice_slot_count();
    const int minutes = s.practice_minutes();
    // In a study the learner must not learn their condition: neither its name nor its budget is shown.
    const bool blinded = !s.settings().study.empty();
    const std::string arm = blinded ? "" : " (" + std::string(condition_name(s.settings().condition)) + ")";
    ImGui::Text("This round: %d practice trial%s, each after a demo; up to about %d minute%s of practice%s.", trials,
                trials == 1 ? "" : "s", minutes, minutes == 1 ? "" : "s", arm.c_str());
    if (!blinded && s.settings().condition != StudyCondition::Adaptive)  // research mode: the arm's share of the budget
      ImGui::TextDisabled("Practice time-steps %d of a budget of %d (reference: %s).", s.curriculum().total_steps(),
                          s.curriculum().budget_steps, budget_reference(s.curriculum_config()).c_str());
    learn_ui::muted_wrapped("You can ask for one more on a skill after any practice trial, or end practice early.");
    if (learn_ui::primary_button(ui, "Start the drills") || confirm_) ui.navigator.go_to(screen_for_phase(s.phase()));
    confirm_ = false;
    learn_ui::end_card();
  }

  // Quality-aware expertise measured against the learner's own hand as well (execution_expertise.hpp): say so
  // and show it, or a learner whose letters all differ from the guide wonders why only one of them is called an
  // error. Returns the height it took beyond the line of text.
  float draw_learner_hand(UiContext& ui, const TrainingSession& s) {
    const std::string& name = s.diagnosis().learner_hand;
    if (name.empty()) return 0.0f;
    if (hand_round_ != s.round() || hand_session_ != &s || hand_for_ != s.diagnosis().expertise) {
      hand_round_ = s.round();
      hand_session_ = &s;
      hand_for_ = s.diagnosis().expertise;
      hand_ = learner_hand_picture(s);
    }
    learn_ui::muted_wrapped(("Your letters follow a hand of your own, closest to " + name +
                             (hand_ ? " (below, your first word over the guide and over that hand)" : "") +
                             ". Each skill was compared with the guide and with that hand; only what is far from "
                             "both counts as an error.")
                                .c_str());
    if (!hand_) return 0.0f;
    const float top = ImGui::GetCursorPosY();
    hand_picture_row(*hand_, "Your", name, 80 * ui.ui_scale, 16 * ui.ui_scale);
    return ImGui::GetCursorPosY() - top;
  }

  AppServices& services_;
  LearnFlow& flow_;
  int hand_round_ = -1;
  const TrainingSession* hand_session_ = nullptr;
  std::vector<double> hand_for_;  // the diagnosis shown when hand_ was drawn from it
  std::optional<LearnerHandTraces> hand_;
  DiagnosisRowPictures pictures_;
  int frames_ = 0;
  bool confirm_ = false;
};

const ScreenRegistration kLearnDiagnosisScreenRegistration{
    {"learn_diagnosis", "Trainer: analysis progress and per-skill diagnosis",
     [](AppServices& services) { return std::make_unique<LearnDiagnosisScreen>(services); }}};

}  // namespace
}  // namespace sc
