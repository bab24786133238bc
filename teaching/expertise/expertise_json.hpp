#pragma once
// JSON form of an ExpertiseEstimate (the `diagnose` command's output, the learner database's diagnoses):
//   {"expertise":[E_0,...], "occurrences":[...], "ranking":[...], "targets":[...],
//    "contributions":[[{"trial":0,"scenario":4,"position":1,"reward":-0.3,"delta":0.3}, ...], ...],
//    "learner_hand": "..." (only when not empty)}
// (contributions[m] lists skill m's penalties). Reading validates sizes and skill ids with JsonView errors.
#include "engine/core/json_file.hpp"
#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

Json expertise_to_json(const ExpertiseEstimate& estimate);
ExpertiseEstimate expertise_from_json(const JsonView& view);

}  // namespace sc
