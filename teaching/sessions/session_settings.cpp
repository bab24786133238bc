#include "teaching/sessions/session_settings.hpp"

#include "engine/core/error.hpp"

namespace sc {

void SessionSettings::validate() const {
  if (learner.empty()) throw InputError("session settings", "the learner's name is empty");
  if (device.empty()) throw InputError("session settings", "the input device is empty");
  if (pretest_count < 1 || pretest_count > 50)
    throw InputError("session settings", "pretest_count must be within 1..50, got " + std::to_string(pretest_count));
  if (eval_count < 1 || eval_count > 50)
    throw InputError("session settings", "eval_count must be within 1..50, got " + std::to_string(eval_count));
  if (weak_skills < 1 || weak_skills > 10)
    throw InputError("session settings", "weak_skills must be within 1..10, got " + std::to_string(weak_skills));
  if (drills_per_weak_skill < 1 || drills_per_weak_skill > 5)
    throw InputError("session settings",
                     "drills_per_weak_skill must be within 1..5, got " + std::to_string(drills_per_weak_skill));
}

Json settings_to_json(const SessionSettings& settings) {
  Json json{{"pretest_count", settings.pretest_count},
            {"eval_count", settings.eval_count},
            {"device", settings.device},
            {"weak_skills", settings.weak_skills},
            {"drills_per_weak_skill", settings.drills_per_weak_skill}};
  if (settings.goal_region) json["goal_region"] = std::string(to_string(*settings.goal_region));
  return json;
}

void read_settings_json(const JsonView& view, SessionSettings& settings) {
  if (auto v = view.find("pretest_count")) settings.pretest_count = static_cast<int>(v->integer());
  if (auto v = view.find("eval_count")) settings.eval_count = static_cast<int>(v->integer());
  if (auto v = view.find("device")) settings.device = v->string();
  if (auto v = view.find("weak_skills")) settings.weak_skills = static_cast<int>(v->integer());
  if (auto v = view.find("drills_per_weak_skill")) settings.drills_per_weak_skill = static_cast<int>(v->integer());
  // Parking sessions recorded before the study corner existed have none: they ran on the whole lot (lot()).
  settings.goal_region.reset();
  if (auto v = view.find("goal_region")) settings.goal_region = parse_goal_region(v->string(), v->path());
}

SessionSettings settings_of_session(const records::SessionRow& row) {
  const std::string where = "session " + std::to_string(row.id) + " settings";
  SessionSettings settings;
  settings.learner = row.learner;
  settings.condition = parse_condition(row.condition);
  settings.seed = row.seed;
  settings.study = row.study;
  const Json json = parse_json_text(row.settings_json, where);
  read_settings_json(JsonView(json, where), settings);
  settings.validate();
  return settings;
}

GoalRegion first_session_goal_region(int earlier_parking_sessions) {
  return earlier_parking_sessions == 0 ? GoalRegion::StudyCorner : GoalRegion::WholeLot;
}

}  // namespace sc
