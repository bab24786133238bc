// Storage faults: a trial that cannot be written (disk full, read-only file or directory, locked
// database) is kept pending in memory and in the spill file, reported in one line, and written as soon
// as the database allows it. Nothing is lost.
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "teaching/records/learner_store.hpp"
#include "teaching/records/pending_writes.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::fresh_dir;
using test::sample_session;
using test::sample_trial;

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Every trial of the session is there, in order, with its trajectory intact.
void expect_trials(const LearnerStore& store, std::int64_t session_id, int count) {
  const auto trials = store.trials_of_session(session_id);
  ASSERT_EQ(trials.size(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(trials[static_cast<std::size_t>(i)].seq, i + 1);
    EXPECT_EQ(trials[static_cast<std::size_t>(i)].record.trajectory_json, sample_trial(session_id, i).trajectory_json);
  }
}

// A directory that the unprivileged child can own (root ignores permissions, so those tests drop to nobody).
// The child drops to uid 65534, which must be able to reach the folder: the build tree may sit under a
// private directory (a fresh clone in a mktemp -d folder is 0700), so these folders live in the system's
// temporary directory instead.
std::filesystem::path dir_for_child(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("skillcoach-records-" + std::to_string(getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  if (geteuid() == 0 && chown(dir.c_str(), 65534, 65534) != 0) ADD_FAILURE() << "chown failed";
  return dir;
}

TEST(LearnerStoreFaults, DiskFullKeepsEveryRecordAndTheNextStoreSavesIt) {
  const auto dir = fresh_dir("disk-full");
  std::int64_t id = 0;
  std::int64_t pages = 0;
  {
    LearnerStore store(dir);
    id = store.begin_session(sample_session());
    ASSERT_TRUE(store.record_trial(sample_trial(id, 0)).stored);
    pages = SqliteDb(store.database_path(), SqliteDb::Mode::ReadOnly).query_int("PRAGMA page_count");
  }
  {
    // The database may not grow by a single page: it is "full".
    LearnerStore store(dir, StoreOptions{.max_page_count = pages});
    const auto first = store.record_trial(sample_trial(id, 1));
    EXPECT_FALSE(first.stored);
    EXPECT_EQ(first.pending, 1u);
    EXPECT_TRUE(mentions(first.message, store.database_path().string() + ": 1 record not saved yet")) << first.message;
    EXPECT_TRUE(mentions(first.message, "the disk or the database is full")) << first.message;
    EXPECT_TRUE(mentions(first.message, "kept in memory and in " + store.spill_path().string())) << first.message;
    EXPECT_EQ(first.message.find('\n'), std::string::npos);
    ASSERT_TRUE(std::filesystem::exists(store.spill_path()));
    EXPECT_EQ(read_spill_file(store.spill_path()).size(), 1u);

    EXPECT_EQ(store.record_trial(sample_trial(id, 2)).pending, 2u);
    EXPECT_FALSE(store.save_diagnosis({id, 1, "[0.5]", "[0]", "compile", "m", "t"}).stored);
    EXPECT_FALSE(store.save_curriculum({id, 1, "adaptive", "[]", {{0, "[0]", R"({"g":1})"}}, "t"}).stored);
    EXPECT_FALSE(store.save_progress(id, {1, SessionPhase::Drills, 0}).stored);
    EXPECT_EQ(store.flush().pending, 5u);
    // Resuming sees the pending work.
    const auto resume = store.find_unfinished_session("Ada", "parking");
    ASSERT_TRUE(resume.has_value());
    EXPECT_EQ(resume->trials_done, 3);
    EXPECT_EQ(resume->session.progress, (SessionProgress{1, SessionPhase::Drills, 0}));
    EXPECT_EQ(read_spill_file(store.spill_path()).size(), 5u);
  }  // the database never became writable for this store: the spill file holds everything
  LearnerStore store(dir);
  EXPECT_EQ(store.pending_count(), 0u);
  EXPECT_EQ(store.open_message(), "");
  EXPECT_FALSE(std::filesystem::exists(store.spill_path()));
  expect_trials(store, id, 3);
  EXPECT_EQ(store.diagnoses_of_session(id).size(), 1u);
  ASSERT_EQ(store.curricula_of_session(id).size(), 1u);
  EXPECT_EQ(store.curricula_of_session(id)[0].drills[0].content_json, R"({"g":1})");
  EXPECT_EQ(store.session(id)->progress, (SessionProgress{1, SessionPhase::Drills, 0}));
}

TEST(LearnerStoreFaults, FileSizeLimitFailsWritesUntilLifted) {
  const auto dir = fresh_dir("fsize");
  const int code = test::run_in_child([&] {
    signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG, as on a full disk
    LearnerStore store(dir);
    const auto id = store.begin_session(sample_session());
    EXPECT_TRUE(store.record_trial(sample_trial(id, 0)).stored);
    rlimit limit{};
    getrlimit(RLIMIT_FSIZE, &limit);
    const auto original = limit;
    const auto wal = std::filesystem::path(store.database_path().string() + "-wal");
    limit.rlim_cur = std::max(std::filesystem::file_size(wal), std::filesystem::file_size(store.database_path()));
    setrlimit(RLIMIT_FSIZE, &limit);
    const auto blocked = store.record_trial(sample_trial(id, 1));
    EXPECT_FALSE(blocked.stored);
    EXPECT_TRUE(mentions(blocked.message, "not saved yet")) << blocked.message;
    setrlimit(RLIMIT_FSIZE, &original);
    const auto next = store.record_trial(sample_trial(id, 2));  // retried on the next write
    EXPECT_TRUE(next.stored) << next.message;
    EXPECT_EQ(next.pending, 0u);
    EXPECT_FALSE(std::filesystem::exists(store.spill_path()));
    expect_trials(store, id, 3);
    return 0;
  });
  EXPECT_EQ(code, 0);
}

TEST(LearnerStoreFaults, ReadOnlyDatabaseFileKeepsTrialsUntilWritable) {
  const auto dir = dir_for_child("readonly-file");
  const int code = test::run_in_child(
      [&] {
        std::int64_t id = 0;
        {
          LearnerStore store(dir);
          id = store.begin_session(sample_session());
          store.record_trial(sample_trial(id, 0));
        }
        const auto db = dir / "skillcoach.db";
        std::filesystem::permissions(db, std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
        LearnerStore store(dir);
        EXPECT_FALSE(store.writable());
        const auto result = store.record_trial(sample_trial(id, 1));
        EXPECT_FALSE(result.stored);
        EXPECT_TRUE(mentions(result.message, "read-only")) << result.message;
        EXPECT_TRUE(std::filesystem::exists(store.spill_path()));
        EXPECT_FALSE(store.flush().stored);
        std::filesystem::permissions(db, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
        const auto retried = store.flush();
        EXPECT_TRUE(retried.stored) << retried.message;
        EXPECT_TRUE(store.writable());
        EXPECT_FALSE(std::filesystem::exists(store.spill_path()));
        expect_trials(store, id, 2);
        return 0;
      },
      /*as_nobody=*/true);
  EXPECT_EQ(code, 0);
  std::filesystem::remove_all(dir);
}

TEST(LearnerStoreFaults, ReadOnlyDirectoryKeepsTrialsInMemoryUntilWritable) {
  const auto dir = dir_for_child("readonly-dir");
  const int code = test::run_in_child(
      [&] {
        std::int64_t id = 0;
        {
          LearnerStore store(dir);
          id = store.begin_session(sample_session());
          store.record_trial(sample_trial(id, 0));
        }
        using std::filesystem::perms;
        std::filesystem::permissions(dir, perms::owner_read | perms::owner_exec);
        LearnerStore store(dir);  // still readable
        EXPECT_FALSE(store.writable());
        EXPECT_EQ(store.trials_of_session(id).size(), 1u);
        const auto result = store.record_trial(sample_trial(id, 1));
        EXPECT_FALSE(result.stored);
        // Even the spill file cannot be written: the message says the trial is only in memory.
        EXPECT_TRUE(mentions(result.message, "kept in memory only")) << result.message;
        std::filesystem::permissions(dir, perms::owner_all);
        const auto next = store.record_trial(sample_trial(id, 2));
        EXPECT_TRUE(next.stored) << next.message;
        expect_trials(store, id, 3);
        return 0;
      },
      /*as_nobody=*/true);
  EXPECT_EQ(code, 0);
  std::filesystem::remove_all(dir);
}

TEST(LearnerStoreFaults, LockedDatabaseQueuesInOrderAndCatchesUp) {
  const auto dir = fresh_dir("locked");
  LearnerStore store(dir, StoreOptions{.busy_timeout_ms = 20});
  const auto id = store.begin_session(sample_session());
  ASSERT_TRUE(store.record_trial(sample_trial(id, 0)).stored);
  {
    SqliteDb other(store.database_path(), SqliteDb::Mode::ReadWriteCreate);
    other.exec("BEGIN IMMEDIATE");  // another process holds the write lock
    const auto first = store.record_trial(sample_trial(id, 1));
    EXPECT_FALSE(first.stored);
    EXPECT_TRUE(mentions(first.message, "locked by another program")) << first.message;
    EXPECT_EQ(store.record_trial(sample_trial(id, 2)).pending, 2u);
    // Reading still works while locked (WAL).
    EXPECT_EQ(store.trials_of_session(id).size(), 1u);
    other.exec("COMMIT");
  }
  const auto third = store.record_trial(sample_trial(id, 3));
  EXPECT_TRUE(third.stored) << third.message;
  EXPECT_EQ(store.pending_count(), 0u);
  expect_trials(store, id, 4);
}

// A data directory behind one we may not search: one line for the trainer and the export, never a
// filesystem exception (which would end the program with exit code 1).
TEST(LearnerStoreFaults, ADataDirectoryWeMayNotReachIsOneLine) {
  const auto dir = dir_for_child("unsearchable");
  std::filesystem::create_directories(dir / "locked" / "data");
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::none);
  const int code = test::run_in_child(
      [&] {
        const auto data = dir / "locked" / "data";
        const auto trainer = test::error_of([&] { LearnerStore store(data); });
        EXPECT_TRUE(mentions(trainer, "Permission denied")) << trainer;
        const auto review = test::error_of([&] { LearnerStore store(data, StoreOptions{.read_only = true}); });
        EXPECT_TRUE(mentions(review, data.string() + "/skillcoach.db: cannot be read: Permission denied")) << review;
        return 0;
      },
      /*as_nobody=*/true);
  EXPECT_EQ(code, 0);
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_all);
  std::filesystem::remove_all(dir);
}

// A trial number already taken by a different trial (a second trainer on the session) is never merged
// away: the trial stays pending and the message says why.
TEST(LearnerStoreFaults, ATrialNumberTakenByAnotherTrialIsNotReportedStored) {
  const auto dir = fresh_dir("seq-conflict");
  LearnerStore store(dir);
  const auto id = store.begin_session(sample_session());
  ASSERT_TRUE(store.record_trial(sample_trial(id, 0)).stored);
  {
    SqliteDb other(store.database_path(), SqliteDb::Mode::ReadWriteCreate);
    other.exec(
        "INSERT INTO trials(session_id, seq, kind, round, task, scenario, trajectory, device, started, finished)"
        " VALUES(" +
        std::to_string(id) + ", 2, 'pretest', 1, 'parking', '{}', '{}', 'mouse', 'a', 'b')");
  }
  const auto clash = store.record_trial(sample_trial(id, 1));
  EXPECT_FALSE(clash.stored);
  EXPECT_TRUE(mentions(clash.message, "trial 2 of session 1 is already a different trial")) << clash.message;
  EXPECT_TRUE(mentions(clash.message, "retrying cannot help")) << clash.message;
  EXPECT_EQ(read_spill_file(store.spill_path()).size(), 1u);
  // Once the other trial is gone, the pending one is stored under its number.
  SqliteDb(store.database_path(), SqliteDb::Mode::ReadWriteCreate).exec("DELETE FROM trials WHERE seq = 2");
  EXPECT_TRUE(store.flush().stored);
  expect_trials(store, id, 2);
}

// A database missing a table is not a passing storage fault: no promise of a retry.
TEST(LearnerStoreFaults, AMissingTableIsNotCalledRetryable) {
  const auto dir = fresh_dir("missing-table");
  LearnerStore store(dir);
  const auto id = store.begin_session(sample_session());
  SqliteDb(store.database_path(), SqliteDb::Mode::ReadWriteCreate).exec("DROP TABLE drills");
  const auto result = store.save_curriculum({id, 1, "adaptive", "[]", {{0, "[0]", "{}"}}, "t"});
  EXPECT_FALSE(result.stored);
  EXPECT_TRUE(mentions(result.message, "no such table: drills")) << result.message;
  EXPECT_FALSE(mentions(result.message, "will retry")) << result.message;
  EXPECT_TRUE(store.pending_spilled());
}

TEST(LearnerStoreFaults, UnreadableSpillFileIsMovedAsideNotOverwritten) {
  const auto dir = fresh_dir("bad-spill");
  { LearnerStore store(dir); }
  const auto spill = dir / "skillcoach.db.pending.json";
  test::write_bytes(spill, "{\"format\": \"skillcoach-pending-writes\", \"writes\": [");
  LearnerStore store(dir);
  EXPECT_TRUE(mentions(store.open_message(), spill.string() + ": not valid JSON")) << store.open_message();
  EXPECT_TRUE(mentions(store.open_message(), "moved to " + spill.string() + ".unreadable")) << store.open_message();
  EXPECT_FALSE(std::filesystem::exists(spill));
  EXPECT_EQ(test::file_bytes(spill.string() + ".unreadable"),
            "{\"format\": \"skillcoach-pending-writes\", \"writes\": [");
}

}  // namespace
}  // namespace sc::records
