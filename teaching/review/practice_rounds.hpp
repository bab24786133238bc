#pragma once
// What each round practised, for the instructor review: the stored curriculum's trials and time-steps
// against its budget (the reference arm's length; docs/skills.md, "Teaching rounds"), and how many practice
// trials the learner actually played (extra attempts included, skipped slots not).
#include <string>
#include <vector>

#include "teaching/review/session_record.hpp"

namespace sc::review {

struct PracticeRound {
  int round = 1;
  std::string condition;  // display name, e.g. "Ind. Drills"
  int planned_trials = 0;
  int steps = 0;  // practice time-steps planned
  int budget_steps = 0;
  int played_trials = 0;
};

// One entry per stored curriculum, by round. InputError naming the session for unreadable items_json.
std::vector<PracticeRound> practice_rounds(const SessionRecord& record);

// "Round 1, Ind. Drills: 6 trials planned, 6 played; 152 time-steps of a 152-step budget (+0.0 %)".
std::string practice_round_text(const PracticeRound& round);

}  // namespace sc::review
