#include "app/gui/screens/learn_hand_picture.hpp"

#include <imgui.h>

#include "app/core/review_pictures.hpp"
#include "engine/review_view/overlay_points.hpp"

namespace sc {

std::optional<LearnerHandTraces> learner_hand_picture(const TrainingSession& session) {
  if (session.pretest_trials().empty() || session.pretest_pool_indices().empty()) return std::nullopt;
  const TaskKit& kit = session.kit();
  const ExpertDemo& expert = kit.expert_pool().at(static_cast<std::size_t>(session.pretest_pool_indices().front()));
  return learner_hand_traces(kit, expert.scenario, expert.steps, session.pretest_trials().front(),
                             session.diagnosis().learner_hand);
}

void hand_picture_row(const LearnerHandTraces& traces, const std::string& whose, const std::string& hand,
                      float box_height, float gap) {
  const ImVec2 box((ImGui::GetContentRegionAvail().x - gap) * 0.5f, box_height);
  const float left = ImGui::GetCursorPosX();
  ImGui::TextDisabled("%s word over the guide", whose.c_str());
  ImGui::SameLine(left + box.x + gap);
  ImGui::TextDisabled("%s word over %s", whose.c_str(), hand.c_str());
  const ImVec2 first = ImGui::GetCursorScreenPos();
  review_view::draw_hand_overlay(*ImGui::GetWindowDrawList(), first, ImVec2(first.x + box.x + gap, first.y), box,
                                 hand_overlay(traces));
  ImGui::Dummy(box);
}

}  // namespace sc
