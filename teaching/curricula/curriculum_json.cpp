#include "teaching/curricula/curriculum_json.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "teaching/drills/drill_plan_json.hpp"

namespace sc {

PracticeKind parse_practice_kind(std::string_view key) {
  for (PracticeKind k :
       {PracticeKind::FullTrajectory, PracticeKind::TimeSlice, PracticeKind::Skill, PracticeKind::Drill}) {
    if (key == practice_kind_key(k)) return k;
  }
  throw InputError("practice kind '" + std::string(key) + "'",
                   "unknown; expected full-trajectory, time-slice, skill or drill");
}

Json curriculum_to_json(const Curriculum& curriculum) {
  Json items = Json::array();
  for (const auto& item : curriculum.items) {
    items.push_back({{"kind", practice_kind_key(item.kind)},
                     {"target_skills", item.target_skills},
                     {"sessions", item.sessions},
                     {"steps", item.steps()},
                     {"material", drill_plan_to_json(item.material)}});
  }
  return {{"condition", condition_key(curriculum.condition)},
          {"budget_steps", curriculum.budget_steps},
          {"total_steps", curriculum.total_steps()},
          {"items", std::move(items)}};
}

Curriculum curriculum_from_json(const JsonView& view) {
  Curriculum out;
  const JsonView condition = view.at("condition");
  try {
    out.condition = parse_condition(condition.string());
  } catch (const InputError& e) {
    condition.fail(e.what());
  }
  const long long budget = view.at("budget_steps").integer();
  if (budget < 0) view.at("budget_steps").fail("must be >= 0");
  out.budget_steps = static_cast<int>(budget);
  const JsonView items = view.at("items");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const JsonView v = items.at(i);
    PracticeItem item;
    const JsonView kind = v.at("kind");
    try {
      item.kind = parse_practice_kind(kind.string());
    } catch (const InputError& e) {
      kind.fail(e.what());
    }
    const JsonView targets = v.at("target_skills");
    for (std::size_t k = 0; k < targets.size(); ++k)
      item.target_skills.push_back(static_cast<int>(targets.at(k).integer()));
    const long long sessions = v.at("sessions").integer();
    if (sessions < 1) v.at("sessions").fail("must be >= 1");
    item.sessions = static_cast<int>(sessions);
    item.material = drill_plan_from_json(v.at("material"));
    if (item.material.segments.empty()) v.at("material").fail("a practice item needs at least one segment");
    out.items.push_back(std::move(item));
  }
  return out;
}

}  // namespace sc
