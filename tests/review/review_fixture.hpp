#pragma once
// The fixed learner database the review tests read: one parking session of learner "Ada" (adaptive, seed 7,
// 3 pre-test and 2 evaluation scenarios, the second pre-test trial cut short, two adaptive rounds of drills) played by
// a scripted learner with fixed timestamps, written through the real TrainingSession and LearnerStore. Built once per
// test process into $SKILLCOACH_TEST_OUTPUT/review/<name>/ (deterministic: same bytes of content every time).
//
// The learner is the app's scripted learner (app/core/learn_scripted_learner.hpp, linked from app_core).
#include <cstdint>
#include <filesystem>

#include "teaching/sessions/task_kit.hpp"

namespace sc::test {

struct ReviewFixture {
  std::filesystem::path data_dir;  // holds skillcoach.db
  std::int64_t session_id = 0;
};

// The parking kit (built once per process).
const TaskKit& parking_kit();
const ReviewFixture& parking_review_fixture();

}  // namespace sc::test
