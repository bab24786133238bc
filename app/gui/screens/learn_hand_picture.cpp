#include "app/gui/screens/learn_hand_picture.hpp"

#include <algorithm>
#include <vector>

#include "app/gui/screens/learn_skill_picture.hpp"

namespace sc {
namespace {

std::vector<ImVec2> to_imvec(const std::vector<std::pair<double, double>>& points) {
  std::vector<ImVec2> out;
  for (const auto& [x, y] : points) out.emplace_back(static_cast<float>(x), static_cast<float>(y));
  return out;
}

void include(ImVec2& lo, ImVec2& hi, const std::vector<ImVec2>& points) {
  for (const ImVec2& p : points) {
    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
  }
}

}  // namespace

std::optional<LearnerHandTraces> learner_hand_picture(const TrainingSession& session) {
  if (session.pretest_trials().empty() || session.pretest_pool_indices().empty()) return std::nullopt;
  const TaskKit& kit = session.kit();
  const ExpertDemo& expert = kit.expert_pool().at(static_cast<std::size_t>(session.pretest_pool_indices().front()));
  return learner_hand_traces(kit, expert.scenario, expert.steps, session.pretest_trials().front(),
                             session.diagnosis().learner_hand);
}

void draw_hand_picture(ImDrawList& d, ImVec2 o, ImVec2 box, float gap, const LearnerHandTraces& traces) {
  const std::vector<ImVec2> learner = to_imvec(traces.learner), guide = to_imvec(traces.guide),
                            hand = to_imvec(traces.hand);
  ImVec2 lo(1e30f, 1e30f), hi(-1e30f, -1e30f);
  include(lo, hi, learner);
  include(lo, hi, guide);
  include(lo, hi, hand);
  draw_overlay_points(d, o, box, learner, guide, lo, hi, IM_COL32(91, 155, 255, 80));
  draw_overlay_points(d, ImVec2(o.x + box.x + gap, o.y), box, learner, hand, lo, hi, IM_COL32(120, 220, 170, 90));
}

void hand_picture_row(const LearnerHandTraces& traces, const std::string& whose, const std::string& hand,
                      float box_height, float gap) {
  const ImVec2 box((ImGui::GetContentRegionAvail().x - gap) * 0.5f, box_height);
  const float left = ImGui::GetCursorPosX();
  ImGui::TextDisabled("%s word over the guide", whose.c_str());
  ImGui::SameLine(left + box.x + gap);
  ImGui::TextDisabled("%s word over %s", whose.c_str(), hand.c_str());
  draw_hand_picture(*ImGui::GetWindowDrawList(), ImGui::GetCursorScreenPos(), box, gap, traces);
  ImGui::Dummy(box);
}

}  // namespace sc
