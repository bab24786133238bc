#include "teaching/records/postgres_store.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "teaching/records/pg_schema_migrations.hpp"
#include "tests/records/store_under_test.hpp"

namespace sc::records {
namespace {

using test::sample_session;
using test::sample_trial;

class PostgresStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (test::postgres_skipped()) GTEST_SKIP() << "SKILLCOACH_NO_POSTGRES=1";
  }
};

// Stops (pause) or restarts (resume) the fixture's server, keeping its data.
void server(const std::string& action) {
  const std::string command = std::string("bash ") + std::getenv("SKILLCOACH_TEST_DATA") +
                              "/records/pg_test_server.sh " + action + " " + std::getenv("SKILLCOACH_TEST_PG_HOST");
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
}

TEST_F(PostgresStoreTest, MigratesAnEmptyDatabaseToTheSchemaVersionsOfTheSqliteStore) {
  const auto under = test::fresh_store(test::Backend::Postgres, "pg_schema");
  EXPECT_EQ(under.open()->schema_version(), current_schema_version());
  // Version N means the same tables in both stores.
  ASSERT_EQ(pg_schema_migrations().size(), schema_migrations().size());
  for (std::size_t i = 0; i < schema_migrations().size(); ++i) {
    EXPECT_EQ(pg_schema_migrations()[i].version, schema_migrations()[i].version);
    EXPECT_EQ(pg_schema_migrations()[i].description, schema_migrations()[i].description);
  }
  PgDb raw(under.store, 5);
  EXPECT_EQ(
      raw.query_int("SELECT count(*) FROM pg_tables WHERE schemaname = 'public' AND tablename IN ('learners',"
                    " 'sessions', 'trials', 'diagnoses', 'curricula', 'drills', 'studies', 'study_participants')"),
      8);
  EXPECT_EQ(under.open(StoreOptions{.read_only = true})->schema_version(), current_schema_version());  // idempotent
}

TEST_F(PostgresStoreTest, RefusesAForeignDatabaseAndAnUnreachableServer) {
  const auto url = test::fresh_pg_database("pg_foreign");
  PgDb(url, 5).exec("CREATE TABLE orders(id int)");
  const auto error = test::error_of([&] { PostgresStore store(url, test::fresh_dir("pg_foreign")); });
  EXPECT_NE(error.find("not SkillCoach's"), std::string::npos) << error;
  const auto nowhere = "postgresql://skillcoach@/x?host=" + test::fresh_dir("pg_nowhere").string();
  const auto unreachable = test::error_of([&] { PostgresStore store(nowhere, test::fresh_dir("pg_nowhere")); });
  EXPECT_NE(unreachable.find("cannot be opened (cannot connect"), std::string::npos) << unreachable;
}

TEST_F(PostgresStoreTest, RefusesASecondDesktopOnTheSameLearnerUntilTheFirstCloses) {
  const auto under = test::fresh_store(test::Backend::Postgres, "pg_lock");
  auto first = under.open();
  first->begin_session(sample_session("Ada"));
  const auto second = under.open();
  const auto refused = test::error_of([&] { second->begin_session(sample_session("Ada")); });
  EXPECT_NE(refused.find("\"Ada\" is already training on another desktop"), std::string::npos) << refused;
  EXPECT_NE(test::error_of([&] { second->find_unfinished_session("Ada"); }), "(no error)");
  EXPECT_NO_THROW(second->begin_session(sample_session("Bob")));
  EXPECT_NO_THROW(under.open(StoreOptions{.read_only = true})->list_learners());  // review claims nobody
  first.reset();
  EXPECT_TRUE(second->find_unfinished_session("Ada").has_value());
}

TEST_F(PostgresStoreTest, KeepsTrialsInTheLocalSpillWhileTheServerIsDownAndUploadsThemWhenItReturns) {
  const auto under = test::fresh_store(test::Backend::Postgres, "pg_outage");
  auto store = under.open();
  const auto id = store->begin_session(sample_session());
  ASSERT_TRUE(store->record_trial(sample_trial(id, 0)).stored);
  server("pause");
  const auto during = store->record_trial(sample_trial(id, 1));
  EXPECT_FALSE(during.stored);
  EXPECT_EQ(during.pending, 1u);
  EXPECT_NE(during.message.find("not saved on the server yet (the server cannot be reached"), std::string::npos)
      << during.message;
  EXPECT_NE(during.message.find(store->spill_path().string()), std::string::npos) << during.message;
  EXPECT_EQ(store->spill_path().parent_path(), under.local_dir);
  EXPECT_FALSE(store->record_trial(sample_trial(id, 2)).stored);
  EXPECT_TRUE(store->pending_spilled());
  // The desktop closes while the server is down: the spill file keeps both trials.
  store.reset();
  EXPECT_TRUE(std::filesystem::exists(under.local_dir));
  server("resume");
  store = under.open();  // uploads the spill file
  EXPECT_EQ(store->open_message(), "");
  EXPECT_EQ(store->pending_count(), 0u);
  const auto resume = store->find_unfinished_session("Ada", "parking");
  ASSERT_TRUE(resume.has_value());
  EXPECT_EQ(resume->trials_done, 3);
  EXPECT_TRUE(store->record_trial(sample_trial(id, 3)).stored);
  const auto trials = store->trials_of_session(id);
  ASSERT_EQ(trials.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(trials[static_cast<std::size_t>(i)].seq, i + 1);
    EXPECT_EQ(trials[static_cast<std::size_t>(i)].record.trajectory_json, sample_trial(id, i).trajectory_json);
  }
  EXPECT_FALSE(std::filesystem::exists(store->spill_path()));
}

TEST_F(PostgresStoreTest, AServerRestartMidSessionLosesNothingAndTheNextTrialIsStoredAtOnce) {
  const auto under = test::fresh_store(test::Backend::Postgres, "pg_restart");
  auto store = under.open();
  const auto id = store->begin_session(sample_session());
  ASSERT_TRUE(store->record_trial(sample_trial(id, 0)).stored);
  server("pause");
  server("resume");
  // The old connection is gone with its learner lock: the store reconnects, locks the learner again, writes.
  EXPECT_TRUE(store->record_trial(sample_trial(id, 1)).stored);
  EXPECT_NE(test::error_of([&] { under.open()->begin_session(sample_session("Ada")); }), "(no error)");
  EXPECT_EQ(store->trials_of_session(id).size(), 2u);
  // Starting a session and reading after a restart work at once too.
  server("pause");
  server("resume");
  EXPECT_NO_THROW(store->begin_session(sample_session("Ada", "writing")));
  server("pause");
  server("resume");
  EXPECT_EQ(store->list_learners().at(0).sessions.size(), 2u);
}

// Ten desktops, each with its own learner, write a session at the same moment; every trial a desktop was
// told is stored is on the server, in order.
TEST_F(PostgresStoreTest, TenDesktopsWritingAtOnceKeepEveryTrialTheyWereToldIsStored) {
  constexpr int kDesktops = 10;
  constexpr int kTrials = 12;
  const auto under = test::fresh_store(test::Backend::Postgres, "pg_class");
  under.open();  // the schema, so the desktops do not all wait on the migration lock
  std::vector<pid_t> children;
  for (int d = 0; d < kDesktops; ++d) {
    const pid_t pid = fork();
    if (pid == 0) {
      int kept = 0;
      try {
        auto store = under.open();
        const auto id = store->begin_session(sample_session("Desk " + std::to_string(d)));
        for (int i = 0; i < kTrials; ++i) kept += store->record_trial(sample_trial(id, i)).stored ? 1 : 0;
      } catch (...) {
        _exit(200);
      }
      _exit(kept);
    }
    children.push_back(pid);
  }
  std::vector<int> kept;
  for (pid_t pid : children) {
    int status = 0;
    waitpid(pid, &status, 0);
    kept.push_back(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  const auto learners = under.open(StoreOptions{.read_only = true})->list_learners();
  ASSERT_EQ(learners.size(), static_cast<std::size_t>(kDesktops));
  const auto reader = under.open(StoreOptions{.read_only = true});
  for (int d = 0; d < kDesktops; ++d) {
    EXPECT_EQ(kept[static_cast<std::size_t>(d)], kTrials) << "desktop " << d;
    const auto& learner = learners[static_cast<std::size_t>(d)];
    EXPECT_EQ(learner.name, "Desk " + std::to_string(d));
    ASSERT_EQ(learner.sessions.size(), 1u);
    const auto trials = reader->trials_of_session(learner.sessions[0].session.id);
    ASSERT_EQ(trials.size(), static_cast<std::size_t>(kTrials));
    for (int i = 0; i < kTrials; ++i) EXPECT_EQ(trials[static_cast<std::size_t>(i)].seq, i + 1);
  }
}

TEST(PostgresUrl, HidesThePasswordInMessagesAndFileNames) {
  EXPECT_EQ(redact_password("postgresql://coach:s3cret@db.school/class"), "postgresql://coach:***@db.school/class");
  EXPECT_EQ(redact_password("postgresql://coach@db.school/class"), "postgresql://coach@db.school/class");
  EXPECT_EQ(redact_password("postgresql:///class?host=/run/pg"), "postgresql:///class?host=/run/pg");
  EXPECT_TRUE(is_server_store("postgresql://x/y"));
  EXPECT_TRUE(is_server_store("postgres://x/y"));
  EXPECT_FALSE(is_server_store("/home/ada/.local/share/skillcoach"));
  EXPECT_NE(test::error_of([] { open_record_store("mysql://x/y"); }).find("unknown kind"), std::string::npos);
}

}  // namespace
}  // namespace sc::records
