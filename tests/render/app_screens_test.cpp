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
#include "tests/support/run_skillcoach.hpp"

namespace sc::test {
namespace {

int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

TEST(AppScreens, StartScreenMatchesGolden) {
  const auto out = test_output_dir() / "start_screen.png";
  const CommandResult r = run_skillcoach("screenshot --screen start --size 1280x720 --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(matches_golden(read_png(out), "app/start_screen"));
}

TEST(AppScreens, ScreenshotIsDeterministicAcrossRuns) {
  const auto a = test_output_dir() / "start_a.png", b = test_output_dir() / "start_b.png";
  ASSERT_EQ(run_skillcoach("screenshot --screen start --size 640x360 --out '" + a.string() + "'").exit_code, 0);
  ASSERT_EQ(run_skillcoach("screenshot --screen start --size 640x360 --frames 5 --out '" + b.string() + "'").exit_code,
            0);
  const ImageDifference diff = compare_images(read_png(a), read_png(b), 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
}

TEST(AppScreens, DemoWritesAPngAndPrintsItsPath) {
  const auto out = test_output_dir() / "demo.png";
  std::filesystem::remove(out);
  const CommandResult r = run_skillcoach("demo --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
  EXPECT_EQ(read_png(out).width, 1280);
}

TEST(AppScreens, NoDisplayFallsBackToTheDemoAndSaysSo) {
  const auto dir = test_output_dir() / "no_display";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / "skillcoach-demo.png");
  const CommandResult r = run_skillcoach("", "cd '" + dir.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skillcoach-demo.png"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "skillcoach-demo.png"));
}

TEST(AppScreens, UnknownScreenIsOneLineExitTwo) {
  const CommandResult r = run_skillcoach("screenshot --screen nowhere --out /tmp/x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("nowhere"), std::string::npos);
  EXPECT_NE(r.output.find("start"), std::string::npos);  // lists the registered screens
}

TEST(AppScreens, MissingShadersAndFontsAreOneLineExitTwo) {
  const auto out = test_output_dir() / "never.png";
  CommandResult r =
      run_skillcoach("screenshot --out '" + out.string() + "'", "SKILLCOACH_SHADER_DIR=/nonexistent/shaders");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  // The first shader the screen loads (ImGui's solid fills come before the scene's).
  EXPECT_NE(r.output.find("/nonexistent/shaders/imgui_solid.vert: shader not found"), std::string::npos) << r.output;
  r = run_skillcoach("screenshot --out '" + out.string() + "'", "SKILLCOACH_ASSET_DIR=/nonexistent/assets");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/assets/fonts/DejaVuSans.ttf"), std::string::npos) << r.output;
}

TEST(AppScreens, BadSizeMouseAndBackendAreOneLineExitTwo) {
  CommandResult r = run_skillcoach("screenshot --size 12x-4 --out /tmp/x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
  for (const char* mouse : {"640", "640,-1", "x,3", "640,360,1", "9000,10"}) {
    r = run_skillcoach(std::string("screenshot --mouse ") + mouse + " --out /tmp/x.png");
    EXPECT_EQ(r.exit_code, 2) << mouse;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find("--mouse"), std::string::npos) << r.output;
  }
  r = run_skillcoach("screenshot --out /tmp/x.png", "SKILLCOACH_GL=vulkan");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("SKILLCOACH_GL"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sc::test
