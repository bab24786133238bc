#include "app/gui/screens/review_pages.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "app/core/fitted_text.hpp"
#include "app/gui/navigator.hpp"
#include "app/gui/screens/learn_hand_picture.hpp"
#include "app/gui/screens/learn_skill_picture.hpp"
#include "engine/review_view/review_palette.hpp"

namespace sc {
namespace {

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

std::string session_label(const review::SessionListRow& row) {
  return row.learner + " - " + review::cell_text(row, review::SessionColumn::Task) + " - " + row.condition + " - " +
         review::cell_text(row, review::SessionColumn::Date);
}

// `text` cut to fit `width` pixels in the current font, ending in "..." when cut.
std::string fitted_label(const std::string& text, float width) {
  return fitted_to_width(text, width, [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
}

void world_frame(UiContext& ui, float x, float y, float w, float h) {
  ImGui::GetBackgroundDrawList()->AddRect({x, y}, {x + w, y + h}, IM_COL32(60, 68, 82, 255), 0.0f, 0,
                                          1.0f * ui.ui_scale);
}

// Where a target's largest penalty happened: the pre-test trial over the expert's, the part aligned with the expert's
// segment in orange; pointing at it shows it larger.
void draw_skill_place(const review::SkillPlace& place, const TrialPartPictureData& picture, const std::string& skill,
                      float scale) {
  const ImVec2 size(150 * scale, 64 * scale);
  const std::string label = "trial " + std::to_string(place.seq);
  const auto draw = [&](ImDrawList& d, ImVec2 at, ImVec2 box) {
    draw_trial_part_picture(d, at, box, picture, label.c_str());
  };
  draw(*ImGui::GetWindowDrawList(), ImGui::GetCursorScreenPos(), size);
  ImGui::Dummy(size);
  enlarge_on_hover("Pre-test trial " + std::to_string(place.seq) +
                       " in yellow, over the expert's in blue. Orange: the part that lines up with where the expert "
                       "does \"" +
                       skill + "\" (this skill's largest penalty)",
                   size, draw, 3.5f);
}

}  // namespace

// A list that grows with the session (its trials, the diagnosis of many targets) shows a scrollbar once it is taller
// than its panel: without one nothing says the rest is a wheel away. Panels of fixed content have none.
void begin_review_panel(const char* id, float x, float y, float w, float h, bool scrolls) {
  ImGui::SetNextWindowPos({x, y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({w, h}, ImGuiCond_Always);
  ImGui::Begin(id, nullptr, kPanelFlags | (scrolls ? 0 : ImGuiWindowFlags_NoScrollbar));
}

void draw_review_top_bar(UiContext& ui, ReviewModel& model, ReviewPage& page) {
  const float s = ui.ui_scale;
  begin_review_panel("review_top", 0, 0, static_cast<float>(ui.width), kReviewTopBar * s);
  ImGui::PushFont(ui.fonts.heading);
  ImGui::TextUnformatted("Review");
  ImGui::PopFont();
  struct Tab {
    ReviewPage page;
    const char* label;
  };
  const Tab tabs[] = {{ReviewPage::Sessions, "Sessions"},
                      {ReviewPage::Trial, "Trial viewer"},
                      {ReviewPage::BeforeAfter, "Before / after"},
                      {ReviewPage::Expertise, "Expertise & diagnosis"}};
  for (const Tab& tab : tabs) {
    ImGui::SameLine(0, 18 * s);
    const bool current = page == tab.page;
    const bool needs_session = tab.page != ReviewPage::Sessions && !model.session();
    ImGui::BeginDisabled(needs_session);
    if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_HeaderActive]);
    if (ImGui::Button(tab.label)) page = tab.page;
    if (current) ImGui::PopStyleColor();
    ImGui::EndDisabled();
  }
  const float back_w = 150 * s;
  const float back_x = static_cast<float>(ui.width) - back_w - ImGui::GetStyle().WindowPadding.x;
  if (const auto* row = model.session_row()) {
    ImGui::SameLine(0, 24 * s);
    const std::string label = session_label(*row);  // cut before the Start screen button, whole on hover
    ImGui::TextDisabled("%s", fitted_label(label, back_x - ImGui::GetCursorPosX() - 16 * s).c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", label.c_str());
  }
  ImGui::SameLine(back_x);
  if (ImGui::Button("Start screen", {back_w, 0})) ui.navigator.go_to("start");
  ImGui::End();
  if (!model.message.empty()) {
    begin_review_panel("review_message", 0, static_cast<float>(ui.height) - 40 * s, static_cast<float>(ui.width),
                       40 * s);
    ImGui::TextColored({1.0f, 0.65f, 0.5f, 1.0f}, "%s", model.message.c_str());
    ImGui::End();
  }
}

// Learner, task and date fields above the session list; a date that is not one is named, not applied.
void draw_session_filter(UiContext& ui, ReviewModel& model) {
  const float s = ui.ui_scale;
  ReviewModel::FilterFields& f = model.filter_fields;
  auto label = [&](const char* text) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(text);
    ImGui::SameLine();
  };
  label("Learner");
  ImGui::SetNextItemWidth(220 * s);
  ImGui::InputTextWithHint("##learner", "name or part of it", f.learner.data(), f.learner.size());
  ImGui::SameLine(0, 24 * s);
  label("Task");
  ImGui::SetNextItemWidth(150 * s);
  ImGui::Combo("##task", &f.task, "every task\0parking\0writing\0");
  ImGui::SameLine(0, 24 * s);
  label("From");
  ImGui::SetNextItemWidth(140 * s);
  ImGui::InputTextWithHint("##from", "YYYY-MM-DD", f.from.data(), f.from.size());
  ImGui::SameLine();
  label("to");
  ImGui::SetNextItemWidth(140 * s);
  ImGui::InputTextWithHint("##to", "YYYY-MM-DD", f.to.data(), f.to.size());
  ImGui::SameLine(0, 24 * s);
  if (ImGui::Button("Reload")) model.reload();
}

void draw_review_sessions(UiContext& ui, ReviewModel& model, ReviewPage& page) {
  const float s = ui.ui_scale;
  begin_review_panel("review_sessions", 0, kReviewTopBar * s, static_cast<float>(ui.width),
                     static_cast<float>(ui.height) - kReviewTopBar * s);
  ImGui::TextDisabled(
      "Every session in the learner database (a class's, on a shared store). Click a column to sort; pick a session "
      "to review it.");
  draw_session_filter(ui, model);
  const review::SessionFilter filter = model.filter();
  int shown = 0;
  for (const review::SessionListRow& row : model.rows()) shown += review::matches(row, filter);
  ImGui::TextDisabled("Showing %d of %zu sessions%s", shown, model.rows().size(),
                      shown == 0 && !model.rows().empty() ? ": none matches the filter." : ".");
  for (const auto& [name, bound] : {std::pair{"From", filter.from}, std::pair{"To", filter.to}})
    if (!review::valid_date_bound(bound)) {
      ImGui::SameLine(0, 16 * s);
      ImGui::TextColored({1.0f, 0.65f, 0.5f, 1.0f}, "%s is not a date (YYYY-MM-DD): ignored.", name);
    }
  const ImGuiTableFlags flags = ImGuiTableFlags_Sortable | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  if (ImGui::BeginTable("sessions", 9, flags)) {
    ImGui::TableSetupScrollFreeze(0, 1);
    for (review::SessionColumn c : review::kSessionColumns) {
      const ImGuiTableColumnFlags cf = c == review::SessionColumn::Date ? ImGuiTableColumnFlags_DefaultSort : 0;
      ImGui::TableSetupColumn(std::string(review::column_title(c)).c_str(), cf, 0.0f, static_cast<ImGuiID>(c));
    }
    ImGui::TableSetupColumn("Trials", ImGuiTableColumnFlags_NoSort);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_NoSort);
    ImGui::TableHeadersRow();
    if (ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs && specs->SpecsDirty && specs->SpecsCount > 0) {
      model.sort(static_cast<review::SessionColumn>(specs->Specs[0].ColumnUserID),
                 specs->Specs[0].SortDirection == ImGuiSortDirection_Ascending);
      specs->SpecsDirty = false;
    }
    for (const review::SessionListRow& row : model.rows()) {
      if (!review::matches(row, filter)) continue;
      ImGui::TableNextRow();
      ImGui::PushID(static_cast<int>(row.session_id));
      for (review::SessionColumn c : review::kSessionColumns) {
        ImGui::TableNextColumn();
        const std::string text = review::cell_text(row, c);
        if (c == review::SessionColumn::Improvement && row.improvement)
          ImGui::TextColored(*row.improvement > 0 ? ImVec4(0.45f, 0.85f, 0.75f, 1) : ImVec4(1.0f, 0.6f, 0.4f, 1), "%s",
                             text.c_str());
        else
          ImGui::TextUnformatted(text.c_str());
      }
      ImGui::TableNextColumn();
      ImGui::Text("%d%s", row.trial_count, row.finished ? "" : " (unfinished)");
      ImGui::TableNextColumn();
      const bool selected = model.session() && model.session()->record().session.id == row.session_id;
      if (ImGui::Button(selected ? "Review (selected)" : "Review")) {
        if (!selected) model.select_session(row.session_id);
        page = ReviewPage::Trial;
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  if (model.rows().empty() && model.message.empty()) ImGui::TextDisabled("No sessions yet.");
  ImGui::End();
}

void draw_review_before_after(UiContext& ui, ReviewModel& model, std::size_t& group) {
  const float s = ui.ui_scale, top = kReviewTopBar * s;
  const auto& groups = model.before_after_groups();
  const float list_w = 330 * s;
  begin_review_panel("review_families", 0, top, list_w, static_cast<float>(ui.height) - top);
  ImGui::TextDisabled("Scenario families");
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const std::string label = groups[i].title + "\n   " + std::to_string(groups[i].pretest_seqs.size()) + " before, " +
                              std::to_string(groups[i].eval_seqs.size()) + " after";
    if (ImGui::Selectable(label.c_str(), group == i)) group = i;
  }
  ImGui::Dummy({0, 10 * s});
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled(
      "Orange: the pre-test trials. Teal: the evaluation trials (fresh scenarios of the same "
      "family). Faint ribbons: the experts' paths.");
  ImGui::PopTextWrapPos();
  ImGui::End();
  if (groups.empty()) return;
  group = std::min(group, groups.size() - 1);
  const PixelViewport viewport{list_w, top, static_cast<float>(ui.width) - list_w, static_cast<float>(ui.height) - top};
  const auto& picture = model.before_after_picture(group);
  ui.renderer.set_camera(review_view::before_after_camera(picture, viewport));
  review_view::paint_before_after(ui.renderer, picture);
  world_frame(ui, viewport.x, viewport.y, viewport.width, viewport.height);
  ImDrawList& dl = *ImGui::GetBackgroundDrawList();
  const auto lines = model.before_after_lines(group);
  float y = top + 10 * s;
  dl.AddRectFilled({list_w + 6 * s, top + 4 * s},
                   {list_w + 470 * s, top + 16 * s + ImGui::GetFontSize() * 1.3f * static_cast<float>(lines.size())},
                   IM_COL32(12, 15, 20, 200), 8 * s);
  for (const auto& line : lines) {
    dl.AddText({list_w + 14 * s, y}, IM_COL32(235, 238, 244, 255), line.c_str());
    y += ImGui::GetFontSize() * 1.3f;
  }
}

void draw_review_expertise(UiContext& ui, ReviewModel& model) {
  const float s = ui.ui_scale, top = kReviewTopBar * s;
  const float half = static_cast<float>(ui.width) * 0.5f;
  begin_review_panel("review_chart", 0, top, half, static_cast<float>(ui.height) - top, true);
  ImGui::PushFont(ui.fonts.bold);
  ImGui::TextUnformatted("Expertise per skill across rounds (stored diagnoses)");
  ImGui::PopFont();
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& line : model.practice_lines()) ImGui::TextDisabled("%s", line.c_str());
  ImGui::PopTextWrapPos();
  if (const auto* chart = model.expertise_chart(); chart && !chart->skills.empty()) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 size(width, std::max(ImGui::GetContentRegionAvail().y - 8 * s,
                                      review_view::expertise_chart_height(*chart, s, width, ui.fonts.bold)));
    review_view::draw_expertise_chart(*ImGui::GetWindowDrawList(), at, size, *chart, s, ui.fonts.bold);
    ImGui::Dummy(size);
  } else {
    ImGui::TextDisabled("No diagnosis stored yet (the pre-test is unfinished).");
  }
  ImGui::End();

  begin_review_panel("review_diagnosis", half, top, half, static_cast<float>(ui.height) - top, true);
  ImGui::PushFont(ui.fonts.bold);
  ImGui::TextUnformatted("Diagnosis explained (round 1)");
  ImGui::PopFont();
  const review::DiagnosisExplanation* d = model.diagnosis();
  ImGui::PushTextWrapPos(0.0f);
  if (!d) {
    ImGui::TextDisabled("%s", model.diagnosis_problem.c_str());
  } else {
    ImGui::TextDisabled(
        "%s recomputed from the %d pre-test trials (%s extractor). A skill the expert used at "
        "position j that the learner's trial lacks costs Delta = -r / j (r: that trial's reward)%s.",
        d->mode == ExpertiseMode::Alg2 ? "Alg. 2" : "Quality-aware expertise", d->pretest_trials, d->extractor.c_str(),
        d->mode == ExpertiseMode::Alg2
            ? ""
            : "; one shown but done worse than the learner's other skills costs "
              "Delta = -q / j (q: how far that part's execution score falls beyond the learner's usual "
              "spread and what noise alone does; for a skill a little off every time, beyond what noise does "
              "to a skill every time)");
    if (!d->learner_hand.empty())
      ImGui::TextDisabled(
          "The learner's letters follow a hand of their own, closest to %s: each part was also scored "
          "against that hand, and q is the better of the two scores.",
          d->learner_hand.c_str());
    if (d->hand_traces)
      hand_picture_row(*d->hand_traces, "Trial 1's", d->learner_hand, 64 * ui.ui_scale, 12 * ui.ui_scale);
    ImGui::TextColored(
        d->matches_stored ? ImVec4(0.45f, 0.85f, 0.75f, 1) : ImVec4(1.0f, 0.6f, 0.4f, 1), "%s",
        d->matches_stored
            ? "Matches the stored diagnosis."
            : "Differs from the stored diagnosis (the model, the data or the diagnosis method changed since).");
    for (const auto& skill : d->skills) {
      ImGui::Separator();
      const ImVec2 at = ImGui::GetCursorScreenPos();
      const float fs = ImGui::GetFontSize();
      ImGui::GetWindowDrawList()->AddRectFilled({at.x, at.y + fs * 0.15f}, {at.x + fs * 0.8f, at.y + fs * 0.95f},
                                                model.palette().color_u32(skill.skill), 3.0f);
      ImGui::Dummy({fs, fs});
      ImGui::SameLine();
      ImGui::PushFont(ui.fonts.bold);
      ImGui::Text("skill %d: %s", skill.skill, skill.description.c_str());
      ImGui::PopFont();
      if (const TrialPartPictureData* picture = skill.place ? model.place_picture(skill.skill) : nullptr) {
        draw_skill_place(*skill.place, *picture, skill.description, ui.ui_scale);
        ImGui::SameLine(0, 12 * ui.ui_scale);
      }
      ImGui::BeginGroup();
      ImGui::Text("E = %.3f, used %d time%s by the expert", skill.expertise, skill.occurrences,
                  skill.occurrences == 1 ? "" : "s");
      if (skill.missed.empty()) ImGui::TextDisabled("Never missed (a target by rank among equals).");
      for (const auto& m : skill.missed) {
        ImGui::Bullet();
        ImGui::TextWrapped("%s in pre-test trial %d: j = %d, %s = %.3f, Delta = %.3f",
                           m.repeated    ? "a little off (every time)"
                           : m.execution ? "done badly"
                                         : "missed",
                           m.seq, m.position, m.execution ? "q" : "r", m.reward, m.delta);
      }
      ImGui::EndGroup();
    }
  }
  ImGui::PopTextWrapPos();
  ImGui::End();
}

}  // namespace sc
