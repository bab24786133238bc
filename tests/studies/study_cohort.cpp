#include "tests/studies/study_cohort.hpp"

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

#include "app/core/learn_scripted_learner.hpp"
#include "engine/core/rng.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/sessions/training_session.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc::test {
namespace {

double gain_of(const std::string& condition) {
  if (condition == "skills") return 0.30;
  if (condition == "time-heuristic") return 0.18;
  return 0.06;
}

StudyCohort build_cohort() {
  StudyCohort cohort;
  // One directory per process: ctest runs tests of one binary in separate processes, two at a time.
  cohort.data_dir = scratch_path("studies", "cohort_" + std::to_string(::getpid()));
  std::filesystem::remove_all(cohort.data_dir);
  records::LearnerStore store(cohort.data_dir);
  store.create_study(
      {kCohortStudy, "parking", {"skills", "time-heuristic", "full-trajectory"}, 4, 11, "2024-05-01T09:00:00.000Z"});
  const std::unique_ptr<TaskKit> kit = make_task_kit(TaskKind::parking, {}, GoalRegion::StudyCorner);
  int tick = 0;
  TimestampSource clock = [&tick] {
    char text[40];
    std::snprintf(text, sizeof text, "2024-05-01T%02d:%02d:%02d.000Z", 10 + tick / 3600, tick / 60 % 60, tick % 60);
    ++tick;
    return std::string(text);
  };
  Rng rng(2024);
  for (int i = 0; i < 11; ++i) {
    const std::string learner = "participant " + std::to_string(i + 1);
    const records::StudyParticipant p = store.enrol(kCohortStudy, learner, clock());
    if (i == 10) break;  // enrolled, never started
    SessionSettings settings;
    settings.learner = learner;
    settings.condition = parse_condition(p.condition);
    settings.study = kCohortStudy;
    settings.pretest_count = 2;
    settings.eval_count = 2;
    settings.seed = 100 + static_cast<std::uint64_t>(i);
    settings.goal_region = GoalRegion::StudyCorner;
    TrainingSession session(*kit, store, settings, clock);
    ScriptedRunHooks hooks;
    hooks.skills.pretest = rng.uniform(0.35, 0.65);
    hooks.skills.eval = std::min(0.98, hooks.skills.pretest + gain_of(p.condition) + rng.uniform(-0.05, 0.05));
    if (i == 9) {  // leaves after the pre-test: unfinished
      hooks.stop = [](const TrainingSession& s) { return s.phase() != SessionPhase::Pretest; };
      play_scripted_round(session, hooks);
      continue;
    }
    play_scripted_round(session, hooks);
    session.finish();
  }
  return cohort;
}

}  // namespace

const StudyCohort& study_cohort() {
  static const StudyCohort cohort = build_cohort();
  return cohort;
}

}  // namespace sc::test
