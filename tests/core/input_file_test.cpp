// Only regular files are read as input: a FIFO must not block, a device must not be read without end, a
// directory says so, and a file behind a directory we may not search is one line, not an exception of
// another kind. Each case runs in a child with an alarm, so a regression fails instead of hanging.
#include "engine/core/input_file.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;

// Runs `read` in a child (as uid 65534 when `as_nobody` and we are root, since root ignores permissions)
// and returns what it reported: the InputError text, "(no error)", "other: <what>" for any other
// exception, or "killed" when it blocked until the alarm.
std::string outcome_of(const std::function<void()>& read, bool as_nobody = false) {
  int out[2];
  if (pipe(out) != 0) return "pipe failed";
  const pid_t pid = fork();
  if (pid == 0) {
    close(out[0]);
    alarm(5);
    if (as_nobody && geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(90);
    std::string text = "(no error)";
    try {
      read();
    } catch (const InputError& e) {
      text = e.what();
    } catch (const std::exception& e) {
      text = std::string("other: ") + e.what();
    }
    if (write(out[1], text.data(), text.size()) < 0) _exit(91);
    _exit(0);
  }
  close(out[1]);
  std::string text;
  char buffer[512];
  ssize_t n = 0;
  while ((n = ::read(out[0], buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  close(out[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? "killed" : text;
}

TEST(InputFile, AFifoIsRefusedWithoutBlocking) {
  const auto fifo = test::fresh_scratch_dir("input_file_fifo") / "trial.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(outcome_of([&] { read_json_file(fifo); }), fifo.string() + ": is a FIFO (named pipe), not a regular file");
}

TEST(InputFile, ADeviceIsRefusedInsteadOfReadWithoutEnd) {
  EXPECT_EQ(outcome_of([] { read_json_file("/dev/zero"); }), "/dev/zero: is a device, not a regular file");
}

TEST(InputFile, ADirectorySaysSo) {
  const auto dir = test::fresh_scratch_dir("input_file_dir");
  EXPECT_EQ(outcome_of([&] { read_json_file(dir); }), dir.string() + ": is a directory");
}

TEST(InputFile, AFileLargerThanTheLimitIsRefusedBeforeReading) {
  const auto file = test::fresh_scratch_dir("input_file_big") / "big.json";
  test::write_bytes(file, std::string(2000, ' '));
  EXPECT_EQ(outcome_of([&] { read_input_file(file, 1000); }), file.string() + ": too large (2000 bytes; at most 1000)");
  EXPECT_EQ(read_input_file(file, 2000).size(), 2000u);
}

TEST(InputFile, AFileBehindAnUnsearchableDirectoryIsOneLine) {
  // Under the system temporary directory: the child drops to uid 65534, which must reach the folder.
  const auto dir = fs::temp_directory_path() / ("skillcoach-input-file-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "locked");
  test::write_bytes(dir / "locked" / "trial.json", "{}");
  fs::permissions(dir / "locked", fs::perms::owner_all);  // 0700: nobody else may search it
  const auto file = dir / "locked" / "trial.json";
  EXPECT_EQ(outcome_of([&] { read_json_file(file); }, /*as_nobody=*/geteuid() == 0),
            geteuid() == 0 ? file.string() + ": cannot be read: permission denied" : "(no error)");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sc
