// `skillcoach learn` when the learner's records cannot all be stored: a file-size limit, a disk too full
// even for the spill file, a second trainer on the same learner. The program never dies mid-write, never
// exits 0 with records unsaved, and says where the unsaved records are.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "teaching/records/learner_store.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;

constexpr int kExitRecordsNotSaved = 3;

// Runs `skillcoach <args>` with RLIMIT_FSIZE = `max_file_bytes`, SIGXFSZ left at its default (the kernel
// kills at the limit) unless `ignore_sigxfsz`, as a shell's `ulimit -f` or `trap '' XFSZ` would.
test::CommandResult run_with_file_limit(const std::string& args, rlim_t max_file_bytes, bool ignore_sigxfsz) {
  int out[2];
  if (pipe(out) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(out[1], STDERR_FILENO);
    close(out[0]);
    signal(SIGXFSZ, ignore_sigxfsz ? SIG_IGN : SIG_DFL);
    rlimit limit{max_file_bytes, RLIM_INFINITY};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(126);
    const std::string command = "exec '" + test::skillcoach_binary() + "' " + args;
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  test::CommandResult result;
  char buffer[4096];
  ssize_t n = 0;
  while ((n = read(out[0], buffer, sizeof buffer)) > 0) result.output.append(buffer, static_cast<std::size_t>(n));
  close(out[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

// The trials a run reported ("trial pretest round 1 reward ... kept|pending: ...").
long trials_reported(const std::string& output) {
  long count = 0;
  for (std::size_t at = 0; (at = output.find("\ntrial ", at)) != std::string::npos; ++at) ++count;
  return count + (output.rfind("trial ", 0) == 0 ? 1 : 0);
}

const std::string kSession = "learn --task writing --pretest 3 --eval 2 --learner limit --data-dir ";

// Size of the write-ahead log once the schema, a learner and a session exist: a file-size limit just above
// it lets `learn` start its session and fails the first trial. Measured, not assumed (the schema may grow).
rlim_t log_bytes_after_session_start() {
  const fs::path dir = test::fresh_scratch_dir("learn_probe");
  records::LearnerStore store(dir);
  store.begin_session({"limit", "writing", "adaptive", 1, R"({"pretest_count":3,"eval_count":2})", "t", ""});
  return static_cast<rlim_t>(fs::file_size(dir / "skillcoach.db-wal"));
}

// Peak size of the write-ahead log over a whole session played without a limit. A second connection
// stays open meanwhile, so the program's close does not merge the log into the file and delete it.
rlim_t log_bytes_of_a_whole_session() {
  const fs::path dir = test::fresh_scratch_dir("learn_probe_whole");
  { records::LearnerStore store(dir); }  // the schema
  records::SqliteDb reader(dir / "skillcoach.db", records::SqliteDb::Mode::ReadWriteCreate);
  reader.query_int("PRAGMA user_version");  // maps the log index: the program is no longer the last connection
  const auto run = test::run_skillcoach(kSession + dir.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return static_cast<rlim_t>(fs::file_size(dir / "skillcoach.db-wal"));
}

// ulimit -f: the write past the limit used to kill the program (SIGXFSZ, exit 153) with the trial in hand.
// Now the write fails like a full disk: the trials wait in the spill file, the exit code says so, and the
// next run without the limit stores them.
TEST(LearnCommandStorage, AFileSizeLimitKeepsTrialsInTheSpillAndFailsTheRun) {
  const fs::path dir = test::fresh_scratch_dir("learn_fsize");
  const auto limited = run_with_file_limit(kSession + dir.string(), log_bytes_of_a_whole_session() * 4 / 5, false);
  EXPECT_EQ(limited.exit_code, kExitRecordsNotSaved) << limited.output;
  EXPECT_NE(limited.output.find("not saved yet"), std::string::npos) << limited.output;
  EXPECT_NE(limited.output.find("the next start of SkillCoach on this data directory saves them"), std::string::npos)
      << limited.output;
  ASSERT_TRUE(fs::exists(dir / "skillcoach.db.pending.json"));
  records::LearnerStore store(dir);  // replays the spill file
  EXPECT_EQ(store.pending_count(), 0u);
  EXPECT_FALSE(fs::exists(dir / "skillcoach.db.pending.json"));
  const auto sessions = store.list_learners().at(0).sessions;
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_TRUE(sessions[0].session.finished.has_value());
  const auto trials = store.trials_of_session(sessions[0].session.id);
  // `learn` prints a line for every scored trial; the demos before each practice trial are stored too.
  long scored = 0;
  for (const auto& t : trials) scored += t.record.kind != records::TrialKind::Demo ? 1 : 0;
  EXPECT_EQ(scored, trials_reported(limited.output));
  for (std::size_t i = 0; i < trials.size(); ++i) EXPECT_EQ(trials[i].seq, static_cast<int>(i) + 1);
}

// A disk too full even for the spill file: the trials exist only in memory. The run used to print
// "finished session" and exit 0; it must say the records are lost and fail.
TEST(LearnCommandStorage, RecordsThatCannotBeKeptAnywhereFailTheRunLoudly) {
  const fs::path dir = test::fresh_scratch_dir("learn_full");
  const auto full = run_with_file_limit(kSession + dir.string(), log_bytes_after_session_start() + 2 * 4120, true);
  EXPECT_EQ(full.exit_code, kExitRecordsNotSaved) << full.output;
  EXPECT_NE(full.output.find("kept in memory only"), std::string::npos) << full.output;
  EXPECT_NE(full.output.find("they are lost when this program ends"), std::string::npos) << full.output;
}

// Two trainers on one learner: the second is refused at once (exit 2), never merged into the first's
// session; another learner may train at the same time.
TEST(LearnCommandStorage, ASecondTrainerOnTheSameLearnerIsRefused) {
  const fs::path dir = test::fresh_scratch_dir("learn_twice");
  const std::string args = "learn --task parking --pretest 3 --eval 2 --data-dir " + dir.string();
  int out[2];
  ASSERT_EQ(pipe(out), 0);
  const pid_t first = fork();
  if (first == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    const std::string command =
        "exec '" + test::skillcoach_binary() + "' " + args + " --learner same --trial-delay-ms 5000";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  FILE* stream = fdopen(out[0], "r");
  char line[512];
  bool started = false;
  while (!started && fgets(line, sizeof line, stream)) started = std::string(line).rfind("started session", 0) == 0;
  ASSERT_TRUE(started);
  const auto second = test::run_skillcoach(args + " --learner same");
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("learner \"same\" is already training in another SkillCoach"), std::string::npos)
      << second.output;
  kill(first, SIGKILL);
  waitpid(first, nullptr, 0);
  fclose(stream);
  const auto other = test::run_skillcoach(args + " --learner same");  // the first is gone: free again
  EXPECT_EQ(other.exit_code, 0) << other.output;
  records::LearnerStore store(dir);
  const auto sessions = store.list_learners().at(0).sessions;
  ASSERT_EQ(sessions.size(), 1u);  // resumed, not a second session merged in
  const auto trials = store.trials_of_session(sessions[0].session.id);
  long evals = 0;
  for (const auto& t : trials) evals += t.record.kind == records::TrialKind::Eval;
  EXPECT_EQ(evals, 2);
}

}  // namespace
}  // namespace sc
