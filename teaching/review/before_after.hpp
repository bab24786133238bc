#pragma once
// Before/after: the pre-test trials and the evaluation trials of a session grouped by scenario family, so
// one picture per family overlays "before" and "after" (the paper's appendix figure). Pre-test and
// evaluation scenarios are different by design (fresh scenarios), so trials are grouped by a coarse family
// rather than by scenario: parking, the goal's side of the aisle and of the start (and backed-in goals
// apart); writing, the alphabet.
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/core/task_kind.hpp"
#include "teaching/review/session_record.hpp"

namespace sc::review {

struct BeforeAfterGroup {
  std::string family;             // key, e.g. "parking-lower-left" (file names)
  std::string title;              // plain words, e.g. "goal in the lower row, left of the start"
  std::vector<int> pretest_seqs;  // trial seqs, in order
  std::vector<int> eval_seqs;     // evaluation trials of every round
};

struct ScenarioFamily {
  std::string key;
  std::string title;
};
// Throws InputError naming `where` for a scenario the task cannot read.
ScenarioFamily scenario_family(TaskKind task, const Json& scenario, const std::string& where);

// Groups ordered by family key; a family appears when it has a pre-test or an evaluation trial.
std::vector<BeforeAfterGroup> before_after_groups(const SessionRecord& record);

}  // namespace sc::review
