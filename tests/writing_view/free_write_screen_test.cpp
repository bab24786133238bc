// The "free_write" screen as a user's screenshot makes it: headless, a scripted hand writes the seeded word
// and the score is shown, so the image is deterministic and matches its golden.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

int run_skillcoach(const std::string& arguments, std::string& output) {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  if (binary == nullptr) throw std::runtime_error("SKILLCOACH_BINARY is not set");
  // Appended piece by piece: g++ 12 reports a false -Wrestrict for "'" + std::string(...) + ... chains.
  std::string command = "'";
  command += binary;
  command += "' ";
  command += arguments;
  command += " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(FreeWriteScreen, HeadlessScreenshotMatchesGoldenAndIsDeterministic) {
  const auto a = test_output_dir() / "free_write_a.png", b = test_output_dir() / "free_write_b.png";
  std::string output;
  ASSERT_EQ(run_skillcoach("screenshot --screen free_write --size 1280x720 --out '" + a.string() + "'", output), 0)
      << output;
  ASSERT_EQ(run_skillcoach("screenshot --screen free_write --size 1280x720 --frames 5 --out '" + b.string() + "'",
                           output),
            0)
      << output;
  const RgbaImage image = read_png(a);
  EXPECT_EQ(compare_images(image, read_png(b), 0).differing_pixels, 0u);
  EXPECT_TRUE(matches_golden(image, "writing/free_write_screen"));
}

}  // namespace
}  // namespace sc::test
