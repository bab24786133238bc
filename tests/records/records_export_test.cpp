#include "teaching/records/records_export.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

#include "teaching/records/sqlite_handle.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::sample_session;
using test::sample_trial;

// Two learners, a session with every kind of record.
std::int64_t fill_fixture(const std::filesystem::path& dir) {
  LearnerStore store(dir);
  store.ensure_learner("Zoe", "2024-04-01T00:00:00.000Z");
  const auto id = store.begin_session(sample_session("Ada"));
  store.record_trial(sample_trial(id, 0, TrialKind::Pretest, -3.0));
  auto demo = sample_trial(id, 1, TrialKind::Demo);
  demo.score.reset();
  demo.drill_index = 0;
  store.record_trial(demo);
  store.record_trial(sample_trial(id, 2, TrialKind::Eval, -1.0));
  store.save_diagnosis({id, 1, "[0.25,0.75]", "[1]", "compile", "model-a", "2024-05-01T10:05:00.000Z"});
  store.save_curriculum({id, 1, "adaptive", R"([{"drill":0}])", {{0, "[1,2]", R"({"ghost":[[0,1]]})"}}, "t"});
  store.finish_session(id, "2024-05-01T11:00:00.000Z");
  return id;
}

TEST(RecordsExport, EmbedsTrajectoriesAsJsonAndKeepsEveryRecord) {
  const auto dir = test::fresh_dir("export");
  const auto id = fill_fixture(dir);
  const LearnerStore store(dir, StoreOptions{.read_only = true});
  const Json doc = export_records(store).doc;
  EXPECT_EQ(doc["format"], "skillcoach-records");
  EXPECT_EQ(doc["schema_version"], store.schema_version());
  ASSERT_EQ(doc["learners"].size(), 2u);
  EXPECT_EQ(doc["learners"][1]["name"], "Zoe");
  EXPECT_TRUE(doc["learners"][1]["sessions"].empty());
  const Json& session = doc["learners"][0]["sessions"][0];
  EXPECT_EQ(session["id"], id);
  EXPECT_EQ(session["finished"], "2024-05-01T11:00:00.000Z");
  EXPECT_EQ(session["settings"]["pretest_count"], 5);
  EXPECT_EQ(session["summary"]["improvement"], 2.0);
  ASSERT_EQ(session["trials"].size(), 3u);
  const Json& trial = session["trials"][0];
  // The trajectory is the trajectory-file document itself, not a string.
  ASSERT_TRUE(trial["trajectory"].is_object());
  EXPECT_EQ(trial["trajectory"], Json::parse(sample_trial(id, 0).trajectory_json));
  EXPECT_EQ(trial["trajectory"]["task"], "parking");
  EXPECT_EQ(trial["scenario"]["variant"], "classic");
  EXPECT_EQ(trial["kind"], "pretest");
  EXPECT_EQ(trial["seq"], 1);
  EXPECT_TRUE(session["trials"][1]["score"].is_null());
  EXPECT_EQ(session["trials"][1]["drill_index"], 0);
  EXPECT_EQ(session["diagnoses"][0]["expertise"], Json::parse("[0.25,0.75]"));
  EXPECT_EQ(session["curricula"][0]["drills"][0]["content"]["ghost"], Json::parse("[[0,1]]"));
  // Deterministic: exporting twice gives the same document.
  EXPECT_EQ(export_records(store).doc.dump(), doc.dump());
}

TEST(RecordsExport, WritesTheFileAndRefusesAMissingOrDamagedDatabase) {
  const auto dir = test::fresh_dir("export-file");
  fill_fixture(dir / "data");
  EXPECT_EQ(export_database(dir / "data", dir / "out.json").trials, 3u);
  EXPECT_EQ(read_json_file(dir / "out.json")["learners"][0]["name"], "Ada");
  EXPECT_EQ(test::error_of([&] { export_database(dir / "nowhere", dir / "x.json"); }),
            (dir / "nowhere" / "skillcoach.db").string() + ": no such database");
  EXPECT_FALSE(std::filesystem::exists(dir / "nowhere"));  // a read-only export creates nothing
  std::filesystem::create_directories(dir / "garbage");
  test::write_bytes(dir / "garbage" / "skillcoach.db", std::string(4096, 'x'));
  EXPECT_NE(test::error_of([&] { export_database(dir / "garbage", dir / "y.json"); }).find("not a SQLite database"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "y.json"));
}

// One damaged row (its JSON no longer parses) is left out and named; everything else is exported.
TEST(RecordsExport, ADamagedRowIsNamedAndTheRestExported) {
  const auto dir = test::fresh_dir("export-damaged");
  const auto id = fill_fixture(dir / "data");
  {
    SqliteDb raw(dir / "data" / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate);
    raw.exec("PRAGMA ignore_check_constraints = ON; UPDATE trials SET trajectory = '{\"cut' WHERE seq = 2");
  }
  const auto result = export_database(dir / "data", dir / "out.json");
  EXPECT_EQ(result.trials, 2u);
  ASSERT_EQ(result.problems.size(), 1u);
  const auto& problem = result.problems[0];
  EXPECT_EQ(problem.rfind((dir / "data" / "skillcoach.db").string() + ": session " + std::to_string(id) +
                              ", trial 2 left out: stored JSON: not valid JSON",
                          0),
            0u)
      << problem;
  const Json doc = read_json_file(dir / "out.json");
  const Json& trials = doc["learners"][0]["sessions"][0]["trials"];
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_EQ(trials[0]["seq"], 1);
  EXPECT_EQ(trials[1]["seq"], 3);
}

// --out naming the database (or its log) would overwrite the learner's records with the export.
TEST(RecordsExport, RefusesToWriteOverTheDatabaseItself) {
  const auto dir = test::fresh_dir("export-over-db");
  fill_fixture(dir);
  const auto db = dir / "skillcoach.db";
  const auto before = test::file_bytes(db);
  const auto message = test::error_of([&] { export_database(dir, db); });
  EXPECT_NE(message.find("is the learner database's own file"), std::string::npos) << message;
  EXPECT_EQ(test::file_bytes(db), before);
  EXPECT_NE(test::error_of([&] { export_database(dir, dir / "." / "skillcoach.db-wal"); }).find("own file"),
            std::string::npos);
}

}  // namespace
}  // namespace sc::records
