#include "app/gui/screens/learn_hand_picture.hpp"

#include <algorithm>

#include "app/gui/screens/learn_skill_picture.hpp"

namespace sc {
namespace {

std::vector<ImVec2> xy_of(const TaskKit& kit, const StepSequence& steps) {
  std::vector<ImVec2> out;
  for (const TracePoint3& p : kit.trace_points(steps))
    out.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
  return out;
}

void include(ImVec2& lo, ImVec2& hi, const std::vector<ImVec2>& points) {
  for (const ImVec2& p : points) {
    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
  }
}

}  // namespace

std::optional<HandPicture> learner_hand_picture(const TrainingSession& session) {
  const std::string& name = session.diagnosis().learner_hand;
  if (name.empty() || session.pretest_trials().empty() || session.pretest_pool_indices().empty()) return std::nullopt;
  const TaskKit& kit = session.kit();
  const ExpertDemo& expert = kit.expert_pool().at(static_cast<std::size_t>(session.pretest_pool_indices().front()));
  const std::vector<ExecutionReference> references = kit.execution_references(expert.scenario, expert.steps);
  const auto hand = std::find_if(references.begin(), references.end(),
                                 [&name](const ExecutionReference& r) { return r.name == name; });
  if (hand == references.end()) return std::nullopt;
  return HandPicture{xy_of(kit, kit.steps_of(session.pretest_trials().front())), xy_of(kit, expert.steps),
                     xy_of(kit, hand->steps)};
}

void draw_hand_picture(ImDrawList& d, ImVec2 o, ImVec2 box, float gap, const HandPicture& picture) {
  ImVec2 lo(1e30f, 1e30f), hi(-1e30f, -1e30f);
  include(lo, hi, picture.learner);
  include(lo, hi, picture.guide);
  include(lo, hi, picture.hand);
  draw_overlay_points(d, o, box, picture.learner, picture.guide, lo, hi, IM_COL32(91, 155, 255, 80));
  draw_overlay_points(d, ImVec2(o.x + box.x + gap, o.y), box, picture.learner, picture.hand, lo, hi,
                      IM_COL32(120, 220, 170, 90));
}

}  // namespace sc
