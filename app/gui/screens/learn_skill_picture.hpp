#pragma once
// A small picture of one expert segment (the skill's example from the pool), drawn with ImGui into a box:
// parking — the car's path over the segment's control steps (re-simulated at sub-step resolution), the
// rest of the manoeuvre faint; writing — the pen path of the segment's share of the gold trajectory.
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "engine/review_view/overlay_points.hpp"
#include "teaching/review/diagnosis_explained.hpp"
#include "teaching/sessions/session_analysis.hpp"

namespace sc {

// What the pictures draw, read from trial documents once: reading a document (and re-simulating a parking path)
// takes about a millisecond a picture, too much to repeat every frame for a page of them (docs/rendering.md).
struct SkillPictureData {
  std::vector<ImVec2> points;       // the expert's whole trial
  std::size_t first = 0, last = 0;  // the segment's points
};
// The skill's example from the pool (example_of_skill), or none when no expert trial shows it.
std::optional<SkillPictureData> skill_example_picture(const std::vector<ExpertDemo>& pool, int skill);

// Both whole trials, the part's points of the learner's.
using TrialPartPictureData = review_view::PartOverlay;
// The learner's control steps [begin, end) of its `steps`.
TrialPartPictureData trial_part_picture_data(const Json& learner_trial, const Json& expert_trial, int begin, int end,
                                             int steps);
// The same for a place of the review's diagnosis (the Review screen and the report).
TrialPartPictureData trial_part_picture_data(const review::SkillPlace& place);

void draw_skill_picture(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const SkillPictureData& picture,
                        bool highlight);

// Where a diagnosis target went wrong: the learner's trial in yellow over the expert's path of the same scenario
// (a faint band), the part in orange, `label` in the corner.
void draw_trial_part_picture(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const TrialPartPictureData& picture,
                             const char* label);

// Before/after pictures: the expert's path of the same scenario as a wide faint band, the learner's path
// over it in yellow, both fitted into the box together.
void draw_overlay_picture(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const Json& learner_trial,
                          const Json& expert_trial);

// While the last item (a picture of `size`) is hovered: a tooltip with `caption` and the picture `zoom` times as
// large, drawn by draw(draw_list, top_left, size). The pictures beside a list are small; pointing at one is how
// to read it.
template <class Draw>
void enlarge_on_hover(const std::string& caption, ImVec2 size, const Draw& draw, float zoom = 4.0f) {
  if (!ImGui::IsItemHovered()) return;
  const ImVec2 large(zoom * size.x, zoom * size.y);
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + large.x);
  ImGui::TextUnformatted(caption.c_str());
  ImGui::PopTextWrapPos();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::Dummy(large);
  draw(*ImGui::GetWindowDrawList(), at, large);
  ImGui::EndTooltip();
}

}  // namespace sc
