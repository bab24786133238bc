#pragma once
// A simulated cohort for the study-report tests: a parking study "cohort" (Skills, Time Heuristic, Full
// Trajectory; 4 per condition, seed 11) in a fresh learner store, 11 participants enrolled through the store's
// randomisation. Nine play a whole session with the app's scripted learner (app/core/learn_scripted_learner.hpp),
// each with their own skill (seeded: pre-test 0.35-0.65, evaluation higher by a condition-dependent gain plus
// noise), 2 pre-test and 2 evaluation scenarios as in the paper's first study; the tenth stops after the
// pre-test (unfinished), the eleventh never starts. Built once per test process.
#include <filesystem>

namespace sc::test {

struct StudyCohort {
  std::filesystem::path data_dir;  // holds skillcoach.db
};

inline constexpr const char* kCohortStudy = "cohort";

const StudyCohort& study_cohort();

}  // namespace sc::test
