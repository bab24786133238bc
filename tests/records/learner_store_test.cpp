#include "teaching/records/learner_store.hpp"

#include <sqlite3.h>

#include <gtest/gtest.h>

#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::fresh_dir;
using test::sample_session;
using test::sample_trial;

TEST(LearnerStore, CreatesAVersionedWalDatabaseInTheDataDirectory) {
  const auto dir = fresh_dir("create") / "nested" / "data";
  {
    LearnerStore store(dir);
    EXPECT_EQ(store.database_path(), dir / "skillcoach.db");
    EXPECT_EQ(store.schema_version(), current_schema_version());
    EXPECT_TRUE(store.writable());
  }
  SqliteDb raw(dir / "skillcoach.db", SqliteDb::Mode::ReadOnly);
  EXPECT_EQ(raw.query_text("PRAGMA journal_mode"), "wal");
  EXPECT_EQ(raw.query_int("PRAGMA application_id"), kSkillCoachApplicationId);
  EXPECT_EQ(raw.query_int("PRAGMA user_version"), current_schema_version());
  for (const char* table : {"learners", "sessions", "trials", "diagnoses", "curricula", "drills"}) {
    auto stmt = raw.prepare("SELECT count(*) FROM sqlite_schema WHERE type = 'table' AND name = ?1");
    stmt.bind(1, std::string_view(table)).step();
    EXPECT_EQ(stmt.column_int(0), 1) << table;
  }
}

TEST(LearnerStore, ReadOnlyStoreReadsButNeverWrites) {
  const auto dir = fresh_dir("readonly-option");
  std::int64_t id = 0;
  {
    LearnerStore store(dir);
    id = store.begin_session(sample_session());
    store.record_trial(sample_trial(id, 0));
  }
  const auto before = test::file_bytes(dir / "skillcoach.db");
  {
    LearnerStore reader(dir, StoreOptions{.read_only = true});
    EXPECT_FALSE(reader.writable());
    EXPECT_EQ(reader.trials_of_session(id).size(), 1u);
    const auto result = reader.record_trial(sample_trial(id, 1));
    EXPECT_FALSE(result.stored);
    EXPECT_NE(result.message.find("opened read-only"), std::string::npos) << result.message;
    EXPECT_NE(test::error_of([&] { reader.begin_session(sample_session()); }).find("opened read-only"),
              std::string::npos);
  }
  EXPECT_EQ(test::file_bytes(dir / "skillcoach.db"), before);
  EXPECT_FALSE(std::filesystem::exists(dir / "skillcoach.db.pending.json"));
  EXPECT_NE(test::error_of([&] {
              LearnerStore missing(dir / "none", StoreOptions{.read_only = true});
            }).find("no such database"),
            std::string::npos);
}

TEST(DataDir, FollowsXdgThenHome) {
  EXPECT_EQ(data_dir_from_environment("/x/data", "/home/a"), std::filesystem::path("/x/data/skillcoach"));
  EXPECT_EQ(data_dir_from_environment("relative/ignored", "/home/a"),
            std::filesystem::path("/home/a/.local/share/skillcoach"));
  EXPECT_EQ(data_dir_from_environment(nullptr, "/home/a"), std::filesystem::path("/home/a/.local/share/skillcoach"));
  EXPECT_NE(test::error_of([] { data_dir_from_environment(nullptr, nullptr); }).find("--data-dir"), std::string::npos);
}

}  // namespace
}  // namespace sc::records
