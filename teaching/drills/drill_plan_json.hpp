#pragma once
// JSON form of a DrillPlan (stored with curricula and drills in the learner database, printed by
// `diagnose`):
//   {"target_skill":3, "ngram":[1,3,4], "ngram_count":12, "repetitions":1,
//    "segments":[{"skill":1,"expert":17,"begin":0,"end":6}, ...]}
// Reading checks that every segment is non-empty and that ids are non-negative; whether an expert index
// exists is checked when the plan is projected (concatenate_expert_steps).
#include "engine/core/json_file.hpp"
#include "teaching/drills/drill_plan.hpp"

namespace sc {

Json drill_plan_to_json(const DrillPlan& plan);
DrillPlan drill_plan_from_json(const JsonView& view);

}  // namespace sc
