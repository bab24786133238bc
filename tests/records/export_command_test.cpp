// `skillcoach export` end to end: the binary exports a database, and refuses a missing or damaged one
// with one error line and exit code 2, leaving the file untouched.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "tests/records/records_test_support.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc::records {
namespace {

TEST(ExportCommand, ExportsADatabaseAndRefusesBadOnesWithExitCode2) {
  ASSERT_TRUE(std::filesystem::exists(sc::test::skillcoach_binary()))
      << sc::test::skillcoach_binary() << " is not built";
  const auto dir = test::fresh_dir("export-command");
  {
    LearnerStore store(dir / "data");
    const auto id = store.begin_session(test::sample_session());
    store.record_trial(test::sample_trial(id, 0));
    store.record_trial(test::sample_trial(id, 1));
  }
  const auto ok = sc::test::run_skillcoach("export --data-dir '" + (dir / "data").string() + "' --out '" +
                                           (dir / "all.json").string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("exported 2 trials"), std::string::npos) << ok.output;
  const Json doc = read_json_file(dir / "all.json");
  EXPECT_EQ(doc["learners"][0]["sessions"][0]["trials"][1]["trajectory"],
            Json::parse(test::sample_trial(1, 1).trajectory_json));

  const auto missing = sc::test::run_skillcoach("export --data-dir '" + (dir / "none").string() + "' --out '" +
                                                (dir / "x.json").string() + "'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.output, "skillcoach: error: " + (dir / "none" / "skillcoach.db").string() + ": no such database\n");

  std::filesystem::create_directories(dir / "bad");
  test::write_bytes(dir / "bad" / "skillcoach.db", std::string(5000, '\x01'));
  const auto bad = sc::test::run_skillcoach("export --data-dir '" + (dir / "bad").string() + "' --out '" +
                                            (dir / "y.json").string() + "'");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.output.rfind("skillcoach: error: " + (dir / "bad" / "skillcoach.db").string() + ": not a SQLite", 0),
            0u)
      << bad.output;
  EXPECT_EQ(test::file_bytes(dir / "bad" / "skillcoach.db"), std::string(5000, '\x01'));
  EXPECT_FALSE(std::filesystem::exists(dir / "y.json"));
}

}  // namespace
}  // namespace sc::records
