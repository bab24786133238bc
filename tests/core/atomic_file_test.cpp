#include "engine/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/core/error.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const char* out = std::getenv("SKILLCOACH_TEST_OUTPUT");
  const fs::path dir = fs::path(out ? out : "/tmp") / ("atomic_file_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int entries_in(const fs::path& dir) {
  return static_cast<int>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, ReplacesTheWholeFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("replace");
  const fs::path file = dir / "trial.json";
  write_file_atomically(file, "first version, longer than the second");
  write_file_atomically(file, std::string("second\0bytes", 12));
  EXPECT_EQ(read_all(file), std::string("second\0bytes", 12));
  EXPECT_EQ(entries_in(dir), 1);
}

TEST(AtomicFile, TemporaryIsASiblingUniqueToTheProcess) {
  const fs::path file = "/data/learner/skillcoach.db.pending.json";
  const fs::path mine = temporary_sibling(file);
  EXPECT_EQ(mine.parent_path(), file.parent_path());
  EXPECT_EQ(mine.extension(), ".tmp");
  EXPECT_NE(mine.filename().string().find(std::to_string(::getpid())), std::string::npos) << mine;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(temporary_sibling(file) == mine ? 1 : 0);  // another process: another name
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "two processes would share one temporary file";
}

TEST(AtomicFile, FailedReplaceNamesTheFileAndRemovesTheTemporary) {
  const fs::path dir = fresh_dir("fail");
  const fs::path target = dir / "export.json";
  fs::create_directories(target / "in-the-way");  // a non-empty directory cannot be replaced by a file
  try {
    write_file_atomically(target, "{}");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(target.string() + ": cannot be replaced: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(entries_in(dir), 1) << "only the directory that was in the way";
  EXPECT_THROW(write_file_atomically(dir / "no-such-dir" / "x.json", "{}"), InputError);
}

TEST(AtomicFile, DurableWriteReplacesTheFileLikeANormalOne) {
  const fs::path dir = fresh_dir("durable");
  const fs::path file = dir / "pending.json";
  write_file_atomically(file, "old", FileDurability::Durable);
  write_file_atomically(file, "new and longer", FileDurability::Durable);
  EXPECT_EQ(read_all(file), "new and longer");
  EXPECT_EQ(entries_in(dir), 1);
}

// A write that stops half-way (here a file-size limit, which fails like a full disk: EFBIG) keeps the old
// file whole, removes the temporary and says "write failed (disk full?)". In a child: the limit is per process.
TEST(AtomicFile, WriteFailingHalfWayKeepsTheOldFileAndRemovesTheTemporary) {
  for (const FileDurability durability : {FileDurability::Normal, FileDurability::Durable}) {
    const fs::path dir = fresh_dir(durability == FileDurability::Durable ? "full_durable" : "full_normal");
    const fs::path file = dir / "trial.json";
    write_file_atomically(file, "the old, complete file");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::signal(SIGXFSZ, SIG_IGN);
      rlimit limit{};
      ::getrlimit(RLIMIT_FSIZE, &limit);
      limit.rlim_cur = 4096;
      ::setrlimit(RLIMIT_FSIZE, &limit);
      try {
        write_file_atomically(file, std::string(100000, 'x'), durability);
      } catch (const InputError& e) {
        _exit(std::string(e.what()).rfind(file.string() + ": write failed (disk full?): ", 0) == 0 ? 0 : 3);
      }
      _exit(2);  // no error at all
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no error, 3: another message";
    EXPECT_EQ(read_all(file), "the old, complete file");
    EXPECT_EQ(entries_in(dir), 1) << "the temporary is left over";
  }
}

}  // namespace
}  // namespace sc
