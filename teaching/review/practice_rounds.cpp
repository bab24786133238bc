#include "teaching/review/practice_rounds.hpp"

#include <cstdio>

#include "engine/core/error.hpp"
#include "teaching/curricula/curriculum_json.hpp"

namespace sc::review {

std::vector<PracticeRound> practice_rounds(const SessionRecord& record) {
  std::vector<PracticeRound> out;
  for (const records::CurriculumRecord& stored : record.curricula) {
    const std::string where =
        "session " + std::to_string(record.session.id) + " curriculum of round " + std::to_string(stored.round);
    const Json doc = parse_json_text(stored.items_json, where);
    const Curriculum curriculum = curriculum_from_json(JsonView(doc, where));
    PracticeRound round;
    round.round = stored.round;
    round.condition = std::string(condition_name(curriculum.condition));
    round.planned_trials = curriculum.trials();
    round.steps = curriculum.total_steps();
    round.budget_steps = curriculum.budget_steps;
    round.played_trials = static_cast<int>(record.trials_of(records::TrialKind::Practice, stored.round).size());
    out.push_back(round);
  }
  return out;
}

std::string practice_round_text(const PracticeRound& round) {
  const double off = round.budget_steps > 0 ? 100.0 * (round.steps - round.budget_steps) / round.budget_steps : 0.0;
  char text[256];
  std::snprintf(text, sizeof text,
                "Round %d, %s: %d trial%s planned, %d played; %d time-steps of a %d-step budget (%+.1f %%)",
                round.round, round.condition.c_str(), round.planned_trials, round.planned_trials == 1 ? "" : "s",
                round.played_trials, round.steps, round.budget_steps, off);
  return text;
}

}  // namespace sc::review
