// `skillcoach bench` end to end on one cheap benchmark: the report is written with the machine table,
// the command and one row per repetition set. Nothing about the measured times is asserted.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using ::testing::HasSubstr;

std::filesystem::path output_dir() { return std::getenv("SKILLCOACH_TEST_OUTPUT"); }

int run(const std::string& arguments, const std::filesystem::path& log) {
  const std::string command =
      std::string(std::getenv("SKILLCOACH_BINARY")) + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(BenchCommand, QuickRunOfOneBenchmarkWritesTheReport) {
  const auto out = output_dir() / "bench_command_test" / "benchmarks.md";
  std::filesystem::remove_all(out.parent_path());
  const auto log = output_dir() / "bench_command_test.log";
  ASSERT_EQ(run("bench --quick --filter records/insert_trial_30kB_sync_normal --out " + out.string(), log), 0)
      << read(log);
  const std::string md = read(out);
  EXPECT_THAT(
      md, HasSubstr("skillcoach bench --quick --filter 'records/insert_trial_30kB_sync_normal' --out " + out.string()));
  EXPECT_THAT(md, HasSubstr("| Logical CPUs |"));
  EXPECT_THAT(md, HasSubstr("| records/insert_trial_30kB_sync_normal/real_time | "));  // UseRealTime() suffix
  EXPECT_THAT(md, HasSubstr(" ms | 3 × "));  // three repetitions in --quick mode
  EXPECT_THAT(md, ::testing::Not(HasSubstr("records/insert_trial_30kB/real_time |")));  // filtered out
}

TEST(BenchCommand, FilterMatchingNothingIsAUsageError) {
  const auto log = output_dir() / "bench_command_nothing.log";
  EXPECT_EQ(run("bench --quick --filter no_such_benchmark_xyz --out " + (output_dir() / "never.md").string(), log), 2);
  EXPECT_THAT(read(log), HasSubstr("skillcoach: error: --filter no_such_benchmark_xyz: matches no benchmark"));
  EXPECT_FALSE(std::filesystem::exists(output_dir() / "never.md"));
}

// docs/benchmarks.md keeps full runs only: a quick or filtered run must name its own file.
TEST(BenchCommand, QuickOrFilteredRunWithoutOutIsRefusedBeforeMeasuring) {
  const auto log = output_dir() / "bench_command_no_out.log";
  EXPECT_EQ(run("bench --quick", log), 2);
  EXPECT_THAT(read(log), HasSubstr("skillcoach: error: --quick: its figures are too rough"));
  EXPECT_EQ(run("bench --filter 'render/'", log), 2);
  EXPECT_THAT(read(log), HasSubstr("skillcoach: error: --filter: a partial run would replace the full record"));
}

}  // namespace
