// The skillcoach program's headless rendering paths, run as a user would: the start screen's golden image,
// the headless demo, and one-line errors with exit code 2 for bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

RunResult run(const std::string& arguments, const std::string& env = "") {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  if (binary == nullptr) throw std::runtime_error("SKILLCOACH_BINARY is not set");
  const std::string command = env + " '" + binary + "' " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  RunResult result;
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

TEST(AppScreens, StartScreenMatchesGolden) {
  const auto out = test_output_dir() / "start_screen.png";
  const RunResult r = run("screenshot --screen start --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(matches_golden(read_png(out), "app/start_screen"));
}

TEST(AppScreens, ScreenshotIsDeterministicAcrossRuns) {
  const auto a = test_output_dir() / "start_a.png", b = test_output_dir() / "start_b.png";
  ASSERT_EQ(run("screenshot --screen start --size 640x360 --out '" + a.string() + "'").exit_code, 0);
  ASSERT_EQ(run("screenshot --screen start --size 640x360 --frames 5 --out '" + b.string() + "'").exit_code, 0);
  const ImageDifference diff = compare_images(read_png(a), read_png(b), 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
}

TEST(AppScreens, DemoWritesAPngAndPrintsItsPath) {
  const auto out = test_output_dir() / "demo.png";
  std::filesystem::remove(out);
  const RunResult r = run("demo --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
  EXPECT_EQ(read_png(out).width, 1280);
}

TEST(AppScreens, NoDisplayFallsBackToTheDemoAndSaysSo) {
  const auto dir = test_output_dir() / "no_display";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / "skillcoach-demo.png");
  const RunResult r = run("", "cd '" + dir.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skillcoach-demo.png"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "skillcoach-demo.png"));
}

TEST(AppScreens, UnknownScreenIsOneLineExitTwo) {
  const RunResult r = run("screenshot --screen nowhere --out /tmp/x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("nowhere"), std::string::npos);
  EXPECT_NE(r.output.find("start"), std::string::npos);  // lists the registered screens
}

TEST(AppScreens, MissingShadersAndFontsAreOneLineExitTwo) {
  const auto out = test_output_dir() / "never.png";
  RunResult r = run("screenshot --out '" + out.string() + "'", "SKILLCOACH_SHADER_DIR=/nonexistent/shaders");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/shaders/scene.vert"), std::string::npos) << r.output;
  r = run("screenshot --out '" + out.string() + "'", "SKILLCOACH_ASSET_DIR=/nonexistent/assets");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/assets/fonts/DejaVuSans.ttf"), std::string::npos) << r.output;
}

TEST(AppScreens, BadSizeAndBadBackendAreOneLineExitTwo) {
  RunResult r = run("screenshot --size 12x-4 --out /tmp/x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
  r = run("screenshot --out /tmp/x.png", "SKILLCOACH_GL=vulkan");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("SKILLCOACH_GL"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sc::test
