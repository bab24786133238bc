#include "teaching/records/learner_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "engine/core/error.hpp"

namespace sc::records {
namespace {

// FNV-1a: stable across builds and runs, so every SkillCoach process picks the same byte for a name.
off_t lock_offset(std::string_view learner) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : learner) hash = (hash ^ c) * 1099511628211ull;
  return static_cast<off_t>(hash & ((std::uint64_t{1} << 62) - 1));  // a valid positive offset
}

}  // namespace

LearnerLocks::~LearnerLocks() {
  if (fd_ >= 0) ::close(fd_);  // releases every claim
}

void LearnerLocks::claim(std::string_view learner) {
  if (held_.count(learner) != 0) return;
  if (fd_ < 0) fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) return;
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = lock_offset(learner);
  lock.l_len = 1;
  if (::fcntl(fd_, F_OFD_SETLK, &lock) != 0) {
    if (errno == EAGAIN || errno == EACCES)
      throw InputError(file_.string(), "learner \"" + std::string(learner) +
                                           "\" is already training in another SkillCoach; finish or close it first");
    throw InputError(file_.string(), std::string("cannot lock the learner: ") + std::strerror(errno));
  }
  held_.emplace(learner);
}

}  // namespace sc::records
