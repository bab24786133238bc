// Two trainers on the same learner: the second is refused before any work starts, whether the first is
// another process or another store in this one; a trainer that ends (even by SIGKILL) frees the learner.
#include "teaching/records/learner_lock.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "teaching/records/learner_store.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

using test::error_of;
using test::fresh_dir;
using test::sample_session;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A child process that starts a session for `learner` and then waits to be killed; returns its pid once
// the session exists.
pid_t start_trainer(const std::filesystem::path& dir, const std::string& learner) {
  int ready[2];
  if (pipe(ready) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    close(ready[0]);
    LearnerStore store(dir);
    store.begin_session(sample_session(learner));
    const char ok = 1;
    if (write(ready[1], &ok, 1) != 1) _exit(1);
    pause();
    _exit(0);
  }
  close(ready[1]);
  char ok = 0;
  EXPECT_EQ(read(ready[0], &ok, 1), 1);
  close(ready[0]);
  return pid;
}

void stop(pid_t pid) {
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
}

TEST(LearnerLock, ASecondProcessOnTheSameLearnerIsRefusedUntilTheFirstEnds) {
  const auto dir = fresh_dir("lock-process");
  const pid_t first = start_trainer(dir, "Ada");
  {
    LearnerStore store(dir);
    const auto refused = error_of([&] { store.begin_session(sample_session("Ada")); });
    EXPECT_TRUE(contains(refused, "learner \"Ada\" is already training in another SkillCoach")) << refused;
    EXPECT_TRUE(contains(error_of([&] { store.find_unfinished_session("Ada", "parking"); }), "already training"));
    EXPECT_NO_THROW(store.begin_session(sample_session("Bob")));  // another learner is free
  }
  stop(first);  // SIGKILL: the kernel drops the claim
  LearnerStore store(dir);
  const auto resume = store.find_unfinished_session("Ada", "parking");
  ASSERT_TRUE(resume.has_value());
  EXPECT_EQ(resume->session.learner, "Ada");
}

TEST(LearnerLock, TwoStoresInOneProcessDoNotShareALearner) {
  const auto dir = fresh_dir("lock-store");
  LearnerStore first(dir);
  first.begin_session(sample_session("Ada"));
  EXPECT_NO_THROW(first.begin_session(sample_session("Ada")));  // the holder may start another
  LearnerStore second(dir);
  EXPECT_TRUE(contains(error_of([&] { second.begin_session(sample_session("Ada")); }), "already training"));
  // Reading is not training: a read-only store (review, export) never claims.
  LearnerStore review(dir, StoreOptions{.read_only = true});
  EXPECT_NO_THROW(review.find_unfinished_session("Ada", "parking"));
}

}  // namespace
}  // namespace sc::records
