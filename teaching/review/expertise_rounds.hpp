#pragma once
// Per-skill expertise across the adaptive rounds of a session, as the trainer stored it (one diagnosis per
// round, docs/database.md): what the instructor's expertise chart plots.
#include <optional>
#include <string>
#include <vector>

#include "teaching/review/session_record.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc::review {

struct SkillAcrossRounds {
  int skill = 0;
  std::string description;                       // kit.describe_skill
  std::vector<std::optional<double>> expertise;  // per round (index as `rounds`); empty: no evidence that round
  std::vector<bool> drilled;                     // per round: practised in a played drill or skill item
};

struct ExpertiseRounds {
  std::vector<int> rounds;                // round numbers with a stored diagnosis, ascending
  std::vector<SkillAcrossRounds> skills;  // every skill with evidence in at least one round, by id
  double lowest = 0.0;                    // min expertise over all rounds (<= 0): the chart's scale
};

// Throws InputError naming the session for a diagnosis whose JSON is invalid or has another skill count.
ExpertiseRounds expertise_rounds(const TaskKit& kit, const SessionRecord& record);

}  // namespace sc::review
