// Storage-level crash test: a child process records trials in a loop and is killed with
// SIGKILL in the middle of the session. Every trial it had been told was stored must be there, intact,
// and the session must resume exactly after the last stored trial.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "teaching/records/learner_store.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::sample_trial;

// Child: records trials forever, writing the seq of each stored trial to `report_fd`.
[[noreturn]] void record_until_killed(const std::filesystem::path& dir, std::int64_t session_id, int report_fd) {
  LearnerStore store(dir);
  for (int i = 0;; ++i) {
    auto trial = sample_trial(session_id, i);
    // Alternate kinds so the resume point moves through the flow like a real session.
    trial.kind = i < 5 ? TrialKind::Pretest : TrialKind::Practice;
    trial.progress_after = SessionProgress{1, i < 5 ? SessionPhase::Pretest : SessionPhase::Drills, i + 1};
    const auto result = store.record_trial(trial);
    if (!result.stored) _exit(3);
    const int seq = i + 1;
    if (write(report_fd, &seq, sizeof seq) != static_cast<ssize_t>(sizeof seq)) _exit(4);
  }
}

TEST(LearnerStoreCrash, SigkillMidSessionLosesNoFinishedTrialAndResumesWhereItStopped) {
  const auto dir = test::fresh_dir("sigkill");
  std::int64_t session_id = 0;
  {
    LearnerStore store(dir);
    session_id = store.begin_session(test::sample_session());
  }
  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(pipe_fds[0]);
    record_until_killed(dir, session_id, pipe_fds[1]);
  }
  close(pipe_fds[1]);
  // Kill it while it keeps writing: after 12 reported trials it is in the middle of the 13th or later.
  int last_reported = 0;
  while (last_reported < 12) {
    ASSERT_EQ(read(pipe_fds[0], &last_reported, sizeof last_reported), static_cast<ssize_t>(sizeof last_reported));
  }
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child ended with status " << status;
  // Drain what it reported before dying.
  int seq = 0;
  while (read(pipe_fds[0], &seq, sizeof seq) == static_cast<ssize_t>(sizeof seq)) last_reported = seq;
  close(pipe_fds[0]);

  LearnerStore store(dir);
  const auto trials = store.trials_of_session(session_id);
  // Every reported trial is there; at most one more (committed, killed before it could report).
  ASSERT_GE(trials.size(), static_cast<std::size_t>(last_reported));
  ASSERT_LE(trials.size(), static_cast<std::size_t>(last_reported) + 1);
  for (std::size_t i = 0; i < trials.size(); ++i) {
    EXPECT_EQ(trials[i].seq, static_cast<int>(i) + 1);
    EXPECT_EQ(trials[i].record.trajectory_json, sample_trial(session_id, static_cast<int>(i)).trajectory_json);
  }
  const auto resume = store.find_unfinished_session("Ada", "parking");
  ASSERT_TRUE(resume.has_value());
  EXPECT_EQ(resume->session.id, session_id);
  EXPECT_EQ(resume->trials_done, static_cast<int>(trials.size()));
  // The resume point was committed with the last trial, so it points right after it.
  const int done = static_cast<int>(trials.size());
  EXPECT_EQ(resume->session.progress,
            (SessionProgress{1, done <= 5 ? SessionPhase::Pretest : SessionPhase::Drills, done}));
  // The session continues with the next number.
  ASSERT_TRUE(store.record_trial(sample_trial(session_id, done)).stored);
  EXPECT_EQ(store.trials_of_session(session_id).back().seq, done + 1);
}

}  // namespace
}  // namespace sc::records
