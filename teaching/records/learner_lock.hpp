#pragma once
// One trainer per learner. Two trainers on the same learner would resume the same session twice and
// hand out the same trial numbers, so the second one is refused before any work starts.
//
// A claim is an open-file-description lock (F_OFD_SETLK) on one byte of "<database>.lock", chosen by a
// hash of the learner's name: the kernel drops it when the holder closes the file or ends, even by
// SIGKILL, so a crash never leaves a learner locked; and a second store in the same process is refused
// too (a plain fcntl lock would be shared by the whole process).
#include <filesystem>
#include <set>
#include <string>
#include <string_view>

namespace sc::records {

class LearnerLocks {
 public:
  explicit LearnerLocks(std::filesystem::path lock_file) : file_(std::move(lock_file)) {}
  ~LearnerLocks();
  LearnerLocks(const LearnerLocks&) = delete;
  LearnerLocks& operator=(const LearnerLocks&) = delete;

  // Throws sc::InputError naming the learner when another trainer holds them. Claiming a learner this
  // object already holds does nothing. When the lock file cannot be created (a read-only directory,
  // where nothing can be written anyway) the claim is skipped.
  void claim(std::string_view learner);

 private:
  std::filesystem::path file_;
  int fd_ = -1;
  std::set<std::string, std::less<>> held_;
};

}  // namespace sc::records
