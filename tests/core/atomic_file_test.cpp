#include "engine/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

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

}  // namespace
}  // namespace sc
