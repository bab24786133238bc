// A damaged, foreign or newer database must be refused with one clear line and never be modified.
#include "teaching/records/database_file_check.hpp"

#include <signal.h>
#include <sys/resource.h>

#include <gtest/gtest.h>

#include "teaching/records/learner_store.hpp"
#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::file_bytes;
using test::fresh_dir;

// A real SkillCoach database with a few trials, closed cleanly; returns its path.
std::filesystem::path make_database(const std::filesystem::path& dir, int trials = 3) {
  LearnerStore store(dir);
  const auto id = store.begin_session(test::sample_session());
  for (int i = 0; i < trials; ++i) store.record_trial(test::sample_trial(id, i));
  return store.database_path();
}

// Opening must fail with a single line naming the file and containing `problem`; the bytes stay the same.
void expect_refused(const std::filesystem::path& dir, const std::string& problem) {
  const auto file = dir / "skillcoach.db";
  const auto before = file_bytes(file);
  const auto message = test::error_of([&] { LearnerStore store(dir); });
  EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  EXPECT_NE(message.find("it was not changed"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_EQ(file_bytes(file), before) << "the database file was modified";
  // A second attempt (e.g. the user restarts the app) does not change it either.
  EXPECT_EQ(test::error_of([&] { LearnerStore store(dir); }), message);
  EXPECT_EQ(file_bytes(file), before);
  EXPECT_FALSE(std::filesystem::exists(dir / "skillcoach.db.pending.json"));
}

TEST(DatabaseFileCheck, RefusesGarbageBytes) {
  const auto dir = fresh_dir("garbage");
  std::string garbage;
  for (int i = 0; i < 8192; ++i) garbage.push_back(static_cast<char>((i * 7919) % 251));
  test::write_bytes(dir / "skillcoach.db", garbage);
  expect_refused(dir, "not a SQLite database");
}

TEST(DatabaseFileCheck, RefusesAFileCutInsideTheHeader) {
  const auto dir = fresh_dir("tiny");
  const auto file = make_database(dir);
  test::write_bytes(file, file_bytes(file).substr(0, 60));
  expect_refused(dir, "only 60 bytes");
}

TEST(DatabaseFileCheck, RefusesATruncatedDatabase) {
  const auto dir = fresh_dir("truncated");
  const auto file = make_database(dir, 20);
  const auto bytes = file_bytes(file);
  ASSERT_GT(bytes.size(), 8 * 4096u);
  test::write_bytes(file, bytes.substr(0, bytes.size() / 2 - 100));  // not a whole number of pages
  expect_refused(dir, "not a whole number of 4096-byte pages");
  test::write_bytes(file, bytes.substr(0, 4 * 4096));  // whole pages, but fewer than the header counts
  expect_refused(dir, "truncated: the header counts");
}

// A checkpoint that failed on a full disk writes page 1 (which counts every page) and then cannot grow the
// file; the pages stay in the write-ahead log, so the database is whole and must be accepted.
TEST(DatabaseFileCheck, AcceptsAMainFileShortOfPagesTheLogHolds) {
  const auto dir = fresh_dir("checkpoint-full");
  const auto file = dir / "skillcoach.db";
  const int code = test::run_in_child([&] {
    signal(SIGXFSZ, SIG_IGN);  // the write past the limit fails with EFBIG, as on a full disk
    LearnerStore store(dir);
    const auto id = store.begin_session(test::sample_session());
    for (int i = 0; i < 20; ++i) store.record_trial(test::sample_trial(id, i));
    rlimit limit{};
    getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = std::filesystem::file_size(file);
    setrlimit(RLIMIT_FSIZE, &limit);
    SqliteDb other(file, SqliteDb::Mode::ReadWriteCreate);
    EXPECT_THROW(other.exec("PRAGMA wal_checkpoint(TRUNCATE)"), SqliteError);
    return 0;
  });
  ASSERT_EQ(code, 0);
  ASSERT_GT(std::filesystem::file_size(dir / "skillcoach.db-wal"), 0u);
  EXPECT_EQ(test::error_of([&] { check_database_file(file, current_schema_version()); }), "(no error)");
  LearnerStore store(dir);
  EXPECT_EQ(store.trials_of_session(1).size(), 20u);
}

TEST(DatabaseFileCheck, RefusesADamagedPage) {
  const auto dir = fresh_dir("damaged");
  const auto file = make_database(dir, 20);
  auto bytes = file_bytes(file);
  // Overwrite the b-tree page header of the second page (the first table's root) with garbage.
  for (std::size_t i = 4096; i < 4096 + 64; ++i) bytes[i] = static_cast<char>(0xA5);
  test::write_bytes(file, bytes);
  expect_refused(dir, "damaged database");
}

TEST(DatabaseFileCheck, RefusesANewerSchema) {
  const auto dir = fresh_dir("newer");
  const auto file = make_database(dir);
  {
    SqliteDb raw(file, SqliteDb::Mode::ReadWriteCreate);
    raw.exec("PRAGMA user_version = " + std::to_string(current_schema_version() + 1));
  }
  expect_refused(dir, "written by a newer SkillCoach (schema version " + std::to_string(current_schema_version() + 1) +
                          ", this build understands up to " + std::to_string(current_schema_version()) + ")");
}

TEST(DatabaseFileCheck, RefusesAnotherProgramsSqliteFile) {
  const auto dir = fresh_dir("foreign");
  {
    SqliteDb raw(dir / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate);
    raw.exec("CREATE TABLE photos(id INTEGER PRIMARY KEY, path TEXT); INSERT INTO photos(path) VALUES('a.jpg');");
  }
  expect_refused(dir, "not a SkillCoach database (1 tables, e.g. 'photos')");
  {
    SqliteDb raw(dir / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate);
    raw.exec("PRAGMA application_id = 1234");
  }
  expect_refused(dir, "not a SkillCoach database (application id 0x000004D2)");
}

TEST(DatabaseFileCheck, AcceptsMissingEmptyAndOwnFiles) {
  const auto dir = fresh_dir("accept");
  EXPECT_TRUE(check_database_file(dir / "none.db", 1).is_new);
  test::write_bytes(dir / "empty.db", "");
  EXPECT_TRUE(check_database_file(dir / "empty.db", 1).is_new);
  {
    SqliteDb raw(dir / "blank.db", SqliteDb::Mode::ReadWriteCreate);
    raw.exec("PRAGMA user_version = 0");
  }
  EXPECT_TRUE(check_database_file(dir / "blank.db", 1).is_new);
  const auto state = check_database_file(make_database(dir), current_schema_version());
  EXPECT_FALSE(state.is_new);
  EXPECT_EQ(state.schema_version, current_schema_version());
}

}  // namespace
}  // namespace sc::records
