#include "tests/review/review_fixture.hpp"

#include <unistd.h>

#include <string>

#include <cstdio>
#include <memory>

#include "app/core/learn_scripted_learner.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/sessions/training_session.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc::test {
namespace {

// The app's scripted learner, on a keyboard; `keep_actions` > 0 cuts the attempt short after that many steps.
Json attempt(const Json& reference, double skill, std::uint64_t seed, std::size_t keep_actions = 0) {
  Json trial = scripted_attempt(reference, skill, seed, "keyboard");
  Json& actions = trial.at("actions");
  if (keep_actions > 0 && actions.size() > keep_actions)
    actions.erase(actions.begin() + static_cast<std::ptrdiff_t>(keep_actions), actions.end());
  return trial;
}

ReviewFixture build_fixture() {
  ReviewFixture fixture;
  // One directory per process: ctest runs each test in its own process, two at a time, and two processes
  // rebuilding one shared fixture raced (a report test saw the database change under it).
  fixture.data_dir = scratch_path("review", "fixture_parking_" + std::to_string(::getpid()));
  std::filesystem::remove_all(fixture.data_dir);
  records::LearnerStore store(fixture.data_dir);
  int tick = 0;
  TimestampSource clock = [&tick] {
    char text[40];
    std::snprintf(text, sizeof text, "2024-05-01T10:%02d:%02d.000Z", tick / 60, tick % 60);
    ++tick;
    return std::string(text);
  };
  SessionSettings settings;
  settings.learner = "Ada";
  settings.pretest_count = 3;
  settings.eval_count = 2;
  settings.seed = 7;
  TrainingSession s(parking_kit(), store, settings, clock);
  fixture.session_id = s.session_id();
  int n = 0;
  // Two adaptive rounds, so the review has expertise across rounds (round 2 diagnoses the round-1 practice).
  for (int round = 1; round <= 2; ++round) {
    if (round > 1) s.start_next_round();
    while (s.phase() != SessionPhase::Summary) {
      const std::uint64_t seed = 1000 + static_cast<std::uint64_t>(n++);
      const TrialTimes times{clock(), clock()};
      switch (s.phase()) {
        case SessionPhase::Pretest:
          // The second pre-test trial stops after two control steps (time ran out, or the learner gave up): its
          // steps cannot hold the expert's later skills, so Alg. 2 has misses to explain even with the time
          // heuristic extractor this checkout falls back to without a trained model.
          s.submit_test_trial(attempt(s.test_expert_trial(), 0.6, seed, s.item_index() == 1 ? 2 : 0), times);
          break;
        case SessionPhase::Evaluation:
          s.submit_test_trial(attempt(s.test_expert_trial(), 0.85, seed), times);
          break;
        case SessionPhase::Diagnosis:
          s.analyse();
          break;
        case SessionPhase::Drills: {
          const int item = s.current_item();
          const Json reference = s.kit().drill_trial(s.drill(item));
          s.record_demo(item, reference, times);
          s.submit_practice(attempt(reference, 0.8, seed), times);
          break;
        }
        case SessionPhase::Summary:
          break;
      }
    }
  }
  s.finish();
  return fixture;
}

}  // namespace

const TaskKit& parking_kit() {
  static const std::unique_ptr<TaskKit> kit = make_task_kit("parking");
  return *kit;
}

const ReviewFixture& parking_review_fixture() {
  static const ReviewFixture fixture = build_fixture();
  return fixture;
}

}  // namespace sc::test
