#include "teaching/records/record_store.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/records/store_under_test.hpp"

// The RecordStore contract, run on the SQLite store and on the PostgreSQL store alike.
namespace sc::records {
namespace {

using test::OnEachStore;
using test::sample_session;
using test::sample_trial;

TEST_P(OnEachStore, KeepsTrialsInOrderWithEveryField) {
  const auto under = fresh("trials");
  std::int64_t session_id = 0;
  {
    const auto store = under.open();
    session_id = store->begin_session(sample_session());
    for (int i = 0; i < 3; ++i) {
      auto result = store->record_trial(sample_trial(session_id, i));
      EXPECT_TRUE(result.stored);
      EXPECT_EQ(result.pending, 0u);
      EXPECT_EQ(result.message, "");
    }
    auto demo = sample_trial(session_id, 3, TrialKind::Demo);
    demo.score.reset();
    demo.drill_index = 2;
    demo.device = "gamepad";
    EXPECT_TRUE(store->record_trial(demo).stored);
  }
  const auto reopened = under.open();
  const auto trials = reopened->trials_of_session(session_id);
  ASSERT_EQ(trials.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    const auto expected = sample_trial(session_id, i);
    const auto& got = trials[static_cast<std::size_t>(i)];
    EXPECT_EQ(got.seq, i + 1);
    EXPECT_EQ(got.record.kind, TrialKind::Pretest);
    EXPECT_EQ(got.record.trajectory_json, expected.trajectory_json);
    EXPECT_EQ(got.record.scenario_json, expected.scenario_json);
    EXPECT_EQ(got.record.score, expected.score);
    EXPECT_EQ(got.record.started, expected.started);
    EXPECT_EQ(got.record.finished, expected.finished);
    EXPECT_EQ(got.record.device, "keyboard");
    EXPECT_FALSE(got.record.drill_index.has_value());
  }
  EXPECT_EQ(trials[3].record.kind, TrialKind::Demo);
  EXPECT_FALSE(trials[3].record.score.has_value());
  EXPECT_EQ(trials[3].record.drill_index, 2);
  EXPECT_EQ(trials[3].record.device, "gamepad");
  // The resume point was committed with each trial.
  EXPECT_EQ(reopened->session(session_id)->progress, (SessionProgress{1, SessionPhase::Pretest, 4}));
}

TEST_P(OnEachStore, KeepsDiagnosesAndCurriculaByRoundAndReplacesARedoneRound) {
  const auto under = fresh("diagnoses");
  const auto store = under.open();
  const auto id = store->begin_session(sample_session());
  EXPECT_TRUE(store->save_diagnosis({id, 2, "[0.5,0.1]", "[1]", "compile", "model-2", "t2"}).stored);
  EXPECT_TRUE(store->save_diagnosis({id, 1, "[0.2,0.9]", "[0]", "compile", "model-1", "t1"}).stored);
  const auto diagnoses = store->diagnoses_of_session(id);
  ASSERT_EQ(diagnoses.size(), 2u);
  EXPECT_EQ(diagnoses[0].round, 1);
  EXPECT_EQ(diagnoses[0].expertise_json, "[0.2,0.9]");
  EXPECT_EQ(diagnoses[0].model_id, "model-1");
  EXPECT_EQ(diagnoses[1].targets_json, "[1]");

  CurriculumRecord curriculum{id, 1, "adaptive", R"([{"drill":0,"steps":50}])", {}, "t3"};
  curriculum.drills = {{0, "[3,1]", R"({"ghost":[[0,0],[1,1]]})"}, {1, "[2]", R"({"ghost":[]})"}};
  EXPECT_TRUE(store->save_curriculum(curriculum).stored);
  // Recomputing a round (e.g. after resuming) replaces it, drills included.
  curriculum.drills = {{0, "[4]", R"({"ghost":[[2,2]]})"}};
  EXPECT_TRUE(store->save_curriculum(curriculum).stored);
  const auto curricula = store->curricula_of_session(id);
  ASSERT_EQ(curricula.size(), 1u);
  EXPECT_EQ(curricula[0].condition, "adaptive");
  ASSERT_EQ(curricula[0].drills.size(), 1u);
  EXPECT_EQ(curricula[0].drills[0].skills_json, "[4]");
  EXPECT_EQ(curricula[0].drills[0].content_json, R"({"ghost":[[2,2]]})");
}

TEST_P(OnEachStore, ListsLearnersWithSessionMeansAndImprovement) {
  const auto under = fresh("learners");
  const auto store = under.open();
  store->ensure_learner("Zoe", "2024-04-01T00:00:00.000Z");  // no sessions yet
  const auto id = store->begin_session(sample_session("Ada"));
  store->record_trial(sample_trial(id, 0, TrialKind::Pretest, -4.0));
  store->record_trial(sample_trial(id, 1, TrialKind::Pretest, -2.0));
  store->record_trial(sample_trial(id, 2, TrialKind::Practice, 5.0));  // not part of either mean
  auto round2_pretest = sample_trial(id, 3, TrialKind::Pretest, 100.0);
  round2_pretest.round = 2;  // later rounds' pre-tests do not change the baseline
  store->record_trial(round2_pretest);
  store->record_trial(sample_trial(id, 4, TrialKind::Eval, -1.0));
  auto eval2 = sample_trial(id, 5, TrialKind::Eval, 0.5);
  eval2.round = 2;  // the last round's evaluation counts
  store->record_trial(eval2);
  const auto other = store->begin_session(sample_session("Ada", "writing"));

  const auto learners = store->list_learners();
  ASSERT_EQ(learners.size(), 2u);
  EXPECT_EQ(learners[0].name, "Ada");
  EXPECT_EQ(learners[1].name, "Zoe");
  EXPECT_TRUE(learners[1].sessions.empty());
  ASSERT_EQ(learners[0].sessions.size(), 2u);
  const auto& summary = learners[0].sessions[0];
  EXPECT_EQ(summary.session.id, id);
  EXPECT_EQ(summary.session.task, "parking");
  EXPECT_EQ(summary.session.condition, "adaptive");
  EXPECT_EQ(summary.trial_count, 6);
  EXPECT_DOUBLE_EQ(*summary.pretest_mean, -3.0);
  EXPECT_DOUBLE_EQ(*summary.eval_mean, 0.5);
  EXPECT_DOUBLE_EQ(*summary.improvement, 3.5);
  EXPECT_EQ(learners[0].sessions[1].session.id, other);
  EXPECT_FALSE(learners[0].sessions[1].pretest_mean.has_value());
  EXPECT_FALSE(learners[0].sessions[1].improvement.has_value());
}

TEST_P(OnEachStore, FindsTheUnfinishedSessionAndWhereItStopped) {
  const auto under = fresh("resume");
  std::int64_t id = 0;
  {
    const auto store = under.open();
    const auto done = store->begin_session(sample_session());
    store->finish_session(done, "2024-05-01T11:00:00.000Z");
    EXPECT_FALSE(store->find_unfinished_session("Ada", "parking").has_value());
    id = store->begin_session(sample_session());
    store->record_trial(sample_trial(id, 0));
    store->record_trial(sample_trial(id, 1));
    store->save_progress(id, {1, SessionPhase::Drills, 3});
  }
  const auto store = under.open();
  const auto resume = store->find_unfinished_session("Ada", "parking");
  ASSERT_TRUE(resume.has_value());
  EXPECT_EQ(resume->session.id, id);
  EXPECT_EQ(resume->session.seed, 42u);
  EXPECT_EQ(resume->session.settings_json, R"({"pretest_count":5})");
  EXPECT_EQ(resume->session.progress, (SessionProgress{1, SessionPhase::Drills, 3}));
  EXPECT_EQ(resume->trials_done, 2);
  EXPECT_FALSE(store->find_unfinished_session("Ada", "writing").has_value());
  EXPECT_TRUE(store->find_unfinished_session("Ada").has_value());
  EXPECT_FALSE(store->find_unfinished_session("Bob", "parking").has_value());
  // The next trial continues the numbering.
  store->record_trial(sample_trial(id, 2));
  EXPECT_EQ(store->trials_of_session(id).back().seq, 3);
}

TEST_P(OnEachStore, RejectsInvalidRecordsWithoutQueueingThem) {
  const auto under = fresh("invalid");
  const auto store = under.open();
  const auto id = store->begin_session(sample_session());
  auto bad_json = sample_trial(id, 0);
  bad_json.trajectory_json = "{\"actions\": [";
  EXPECT_EQ(test::error_of([&] { store->record_trial(bad_json); }),
            "learner record: trial trajectory is not valid JSON");
  auto nan_score = sample_trial(id, 0);
  nan_score.score = std::nan("");
  EXPECT_EQ(test::error_of([&] { store->record_trial(nan_score); }), "learner record: trial score is not finite");
  EXPECT_EQ(test::error_of([&] { store->record_trial(sample_trial(id + 99, 0)); }),
            store->database_path().string() + ": unknown session id " + std::to_string(id + 99));
  EXPECT_EQ(test::error_of([&] { store->begin_session(sample_session("")); }), "learner record: learner name is empty");
  // Blank names (the schema's CHECK trims spaces only) and control bytes: a plain message, not SQLite's text.
  EXPECT_EQ(test::error_of([&] { store->begin_session(sample_session("\t\t")); }),
            "learner record: learner name is blank");
  EXPECT_EQ(test::error_of([&] { store->ensure_learner("   ", "t"); }), "learner record: learner name is blank");
  EXPECT_EQ(test::error_of([&] { store->ensure_learner("Ada\x1b[2J", "t"); }),
            "learner record: learner name contains a control character");
  EXPECT_EQ(store->pending_count(), 0u);
  EXPECT_TRUE(store->trials_of_session(id).empty());
}

INSTANTIATE_TEST_SUITE_P(Stores, OnEachStore, ::testing::Values(test::Backend::Sqlite, test::Backend::Postgres),
                         test::backend_name);

}  // namespace
}  // namespace sc::records
