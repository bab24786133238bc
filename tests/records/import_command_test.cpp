// The commands that take --store, end to end against the test server: a desktop's records exported and
// imported into a class's PostgreSQL database, a learner training there with `learn --store`, a study run
// there, the whole store exported back; and an unreachable server refused in one line with exit code 2.
#include <gtest/gtest.h>

#include "tests/records/store_under_test.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc::records {
namespace {

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

TEST(StoreCommands, MoveADesktopsRecordsToTheServerTrainAndRunAStudyThere) {
  if (test::postgres_skipped()) GTEST_SKIP() << "SKILLCOACH_NO_POSTGRES=1";
  const auto dir = test::fresh_dir("store-commands");
  {
    LearnerStore desktop(dir / "desktop");
    const auto id = desktop.begin_session(test::sample_session("Ada"));
    desktop.record_trial(test::sample_trial(id, 0));
    desktop.record_trial(test::sample_trial(id, 1));
  }
  const auto url = "'" + test::fresh_pg_database("cli_store") + "'";
  const auto run = [](const std::string& args) { return sc::test::run_skillcoach(args); };
  auto r = run("export --data-dir " + quoted(dir / "desktop") + " --out " + quoted(dir / "desktop.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run("import --in " + quoted(dir / "desktop.json") + " --store " + url);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("imported 1 learners, 0 studies, 1 sessions and 2 trials"), std::string::npos) << r.output;

  r = run("learn --task parking --pretest 3 --eval 2 --learner Bea --store " + url + " --data-dir " +
          quoted(dir / "seat2"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run("study create --store " + url +
          " --name pilot --task parking --conditions skills,time-heuristic --per-condition 2 --seed 7");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run("study enrol --store " + url + " --study pilot --learner P1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run("study status --store " + url + " --study pilot");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("total"), std::string::npos) << r.output;

  r = run("export --store " + url + " --out " + quoted(dir / "server.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json desktop = read_json_file(dir / "desktop.json");
  const Json server = read_json_file(dir / "server.json");
  ASSERT_EQ(server["learners"].size(), 3u);  // Ada, Bea, P1
  EXPECT_EQ(server["learners"][0]["sessions"][0]["trials"], desktop["learners"][0]["sessions"][0]["trials"]);
  EXPECT_EQ(server["learners"][1]["name"], "Bea");
  EXPECT_GE(server["learners"][1]["sessions"][0]["summary"]["trial_count"].get<int>(), 5);
  EXPECT_EQ(server["studies"][0]["participants"][0]["learner"], "P1");

  const auto nowhere = "'postgresql://skillcoach@/x?host=" + (dir / "no-server").string() + "'";
  r = run("learn --task parking --learner Cy --store " + nowhere + " --data-dir " + quoted(dir / "seat3"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("cannot be opened (cannot connect"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sc::records
