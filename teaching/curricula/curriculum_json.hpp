#pragma once
// JSON form of a Curriculum (research mode, the learner database, resuming a session):
//   {"condition":"ind-drills", "budget_steps":66, "total_steps":63,
//    "items":[{"kind":"drill", "target_skills":[3], "sessions":1, "steps":21, "material":{DrillPlan}}, ...]}
// "total_steps" and "steps" are informative (recomputed on reading).
#include "engine/core/json_file.hpp"
#include "teaching/curricula/curriculum.hpp"

namespace sc {

Json curriculum_to_json(const Curriculum& curriculum);
Curriculum curriculum_from_json(const JsonView& view);
// "full-trajectory", "time-slice", "skill", "drill"; InputError otherwise.
PracticeKind parse_practice_kind(std::string_view key);

}  // namespace sc
