#include "teaching/review/before_after.hpp"

#include <map>

#include "engine/core/error.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::review {

ScenarioFamily scenario_family(TaskKind task, const Json& scenario, const std::string& where) {
  if (task == TaskKind::parking) {
    const ParkingScenario s = parse_parking_scenario(JsonView(scenario, where));
    const Pose goal = goal_pose(s);
    // Spots 0..14 lie at +y, drawn below the aisle (the lot is drawn with +y down).
    const bool lower = spot_pose(s.goal_spot).y > 0;
    const bool left = goal.x < 0;
    ScenarioFamily f;
    f.key = std::string("parking-") + (lower ? "lower" : "upper") + "-" + (left ? "left" : "right") +
            (s.reverse_in ? "-backed-in" : "");
    f.title = std::string("goal in the ") + (lower ? "lower" : "upper") + " row, " + (left ? "left" : "right") +
              " of the start" + (s.reverse_in ? ", backed in" : "");
    return f;
  }
  const writing::WritingScenario s = writing::parse_writing_scenario(JsonView(scenario, where));
  const std::string alphabet = s.alphabet == writing::AlphabetKind::Classic ? "classic" : "balinese";
  return {"writing-" + alphabet, alphabet + " alphabet words"};
}

std::vector<BeforeAfterGroup> before_after_groups(const SessionRecord& record) {
  std::map<std::string, BeforeAfterGroup> groups;
  for (const auto& t : record.trials) {
    const bool pre = t.record.kind == records::TrialKind::Pretest;
    if (!pre && t.record.kind != records::TrialKind::Eval) continue;
    const std::string where =
        "session " + std::to_string(record.session.id) + " trial " + std::to_string(t.seq) + " scenario";
    Json scenario;
    try {
      scenario = Json::parse(t.record.scenario_json);
    } catch (const Json::exception& e) {
      throw InputError(where, std::string("is not JSON: ") + e.what());
    }
    const ScenarioFamily family = scenario_family(parse_task_kind(t.record.task, where), scenario, where);
    BeforeAfterGroup& g = groups[family.key];
    g.family = family.key;
    g.title = family.title;
    (pre ? g.pretest_seqs : g.eval_seqs).push_back(t.seq);
  }
  std::vector<BeforeAfterGroup> out;
  for (auto& [key, group] : groups) out.push_back(std::move(group));
  return out;
}

}  // namespace sc::review
