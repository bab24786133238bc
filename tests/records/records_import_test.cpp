#include "teaching/records/records_import.hpp"

#include <gtest/gtest.h>

#include "teaching/records/records_export.hpp"
#include "tests/records/store_under_test.hpp"

namespace sc::records {
namespace {

using test::sample_session;
using test::sample_trial;

// A study with two participants (one finished session in it), a learner outside it with an unfinished
// session and every kind of record, and a learner without sessions.
void fill(RecordStore& store) {
  store.ensure_learner("Zoe", "2024-04-01T00:00:00.000Z");
  store.create_study(
      {"pilot", "parking", {"skills", "time-heuristic"}, 2, 0xfedcba9876543210ull, "2024-04-02T00:00:00Z"});
  const auto p1 = store.enrol("pilot", "P01", "2024-04-03T00:00:00.000Z");
  store.enrol("pilot", "P02", "2024-04-03T00:10:00.000Z");
  auto in_study = sample_session("P01");
  in_study.condition = p1.condition;
  in_study.study = "pilot";
  const auto s1 = store.begin_session(in_study);
  store.record_trial(sample_trial(s1, 0, TrialKind::Pretest, 0.1 + 0.2));  // not a short decimal: bit-exact?
  store.record_trial(sample_trial(s1, 1, TrialKind::Eval, -1.0 / 3.0));
  store.finish_session(s1, "2024-05-01T11:00:00.000Z");
  const auto s2 = store.begin_session(sample_session("Ada"));
  store.record_trial(sample_trial(s2, 0));
  auto demo = sample_trial(s2, 1, TrialKind::Demo);
  demo.score.reset();
  demo.drill_index = 0;
  store.record_trial(demo);
  store.save_diagnosis({s2, 1, "[0.25,0.75]", "[1]", "compile", "model-a", "2024-05-01T10:05:00.000Z"});
  store.save_curriculum({s2, 1, "adaptive", R"([{"drill":0}])", {{0, "[1,2]", R"({"ghost":[[0,1]]})"}}, "t"});
  store.save_progress(s2, {1, SessionPhase::Drills, 1});
}

// The export without the stores' own ids.
Json without_ids(Json doc) {
  if (doc.is_object()) {
    doc.erase("id");
    doc.erase("session_id");
  }
  if (doc.is_object() || doc.is_array())
    for (auto& child : doc) child = without_ids(child);
  return doc;
}

Json exported(const test::StoreUnderTest& under) {
  return export_records(*under.open(StoreOptions{.read_only = true})).doc;
}

TEST(RecordsImport, MovesEveryRecordFromSqliteToPostgresAndBackWithoutLoss) {
  if (test::postgres_skipped()) GTEST_SKIP() << "SKILLCOACH_NO_POSTGRES=1";
  const auto sqlite = test::fresh_store(test::Backend::Sqlite, "import_source");
  fill(*sqlite.open());
  const Json source = exported(sqlite);

  const auto server = test::fresh_store(test::Backend::Postgres, "import_server");
  const auto counts = import_records(source, "records.json", *server.open());
  EXPECT_EQ(counts.learners, 4u);
  EXPECT_EQ(counts.studies, 1u);
  EXPECT_EQ(counts.sessions, 2u);
  EXPECT_EQ(counts.trials, 4u);
  const Json on_server = exported(server);
  EXPECT_EQ(without_ids(on_server), without_ids(source));
  EXPECT_EQ(on_server["learners"][1]["sessions"][0]["trials"][0]["score"].get<double>(), 0.1 + 0.2);

  const auto back = test::fresh_store(test::Backend::Sqlite, "import_back");
  import_records(on_server, "server.json", *back.open());
  EXPECT_EQ(without_ids(exported(back)), without_ids(source));
}

// A learner who trained on a desktop while the class server was away: the desktop's session joins the ones the
// class store holds for them, and importing the same file again adds nothing.
TEST(RecordsImport, AKnownLearnersOtherSessionsAreAddedAndASecondImportAddsNothing) {
  const auto server = test::fresh_store(test::Backend::Sqlite, "import_class");
  {
    const auto store = server.open();
    const auto s = store->begin_session(sample_session("Ada"));
    store->record_trial(sample_trial(s, 0));
  }
  const auto desktop = test::fresh_store(test::Backend::Sqlite, "import_desktop");
  {
    const auto store = desktop.open();
    auto offline = sample_session("Ada", "writing");
    offline.started = "2024-05-02T09:00:00.000Z";
    const auto s = store->begin_session(offline);
    store->record_trial(sample_trial(s, 0));
    store->record_trial(sample_trial(s, 1));
  }
  const Json offline = exported(desktop);
  auto counts = import_records(offline, "desktop.json", *server.open());
  EXPECT_EQ(counts.learners, 0u);  // Ada was there
  EXPECT_EQ(counts.sessions, 1u);
  EXPECT_EQ(counts.trials, 2u);
  EXPECT_EQ(counts.sessions_already_there, 0u);
  counts = import_records(offline, "desktop.json", *server.open());
  EXPECT_EQ(counts.sessions, 0u);
  EXPECT_EQ(counts.sessions_already_there, 1u);
  const auto learners = server.open(StoreOptions{.read_only = true})->list_learners();
  ASSERT_EQ(learners.size(), 1u);
  ASSERT_EQ(learners[0].sessions.size(), 2u);
  EXPECT_EQ(learners[0].sessions[1].session.task, "writing");
  EXPECT_EQ(learners[0].sessions[1].trial_count, 2);
}

TEST(RecordsImport, RefusesAStoreThatAlreadyHoldsTheStudyAndAnotherFormat) {
  const auto sqlite = test::fresh_store(test::Backend::Sqlite, "import_twice");
  fill(*sqlite.open());
  const Json source = exported(sqlite);
  const auto store = sqlite.open();
  EXPECT_NE(
      test::error_of([&] { import_records(source, "records.json", *store); }).find("already holds the study \"pilot\""),
      std::string::npos);
  EXPECT_EQ(test::error_of([&] {
              import_records(Json{{"format", "other"}, {"version", 1}}, "x.json", *store);
            }),
            "x.json: is not a skillcoach-records export of version 1");
}

}  // namespace
}  // namespace sc::records
