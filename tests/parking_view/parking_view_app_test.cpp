// The parking view through the skillcoach program, run as a user would: `skillcoach render --task parking`
// (plain, with --overlay expert, bad input) and the free-drive screen's headless screenshot.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "engine/parking/parking_trial.hpp"
#include "engine/render/rgba_image.hpp"
#include "tests/support/golden_image.hpp"
#include "tests/support/run_skillcoach.hpp"

namespace sc {
namespace {

std::string quoted(const std::filesystem::path& p) {
  std::string text = "'";
  text.append(p.string()).append("'");
  return text;
}

// Each test writes its own copy: ctest runs the tests of this file in parallel processes, and two atomic
// writes of one file raced (one process renamed the other's temporary file away: "cannot be replaced").
std::filesystem::path learner_trial_file(const std::string& name) {
  ParkingTrial trial;
  trial.scenario.heading0 = 3.51;
  trial.scenario.goal_spot = 7;
  trial.actions.assign(12, ParkingAction{0.6, -0.5});
  trial.source = "learner";
  const auto file = test::test_output_dir() / name;
  write_parking_trial(file, trial);
  return file;
}

// Pixels of one colour (within 2 per channel), to see that something was drawn, not just that a file exists.
int count_colour(const RgbaImage& image, int r, int g, int b) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.at(x, y);
      n += std::abs(p[0] - r) <= 2 && std::abs(p[1] - g) <= 2 && std::abs(p[2] - b) <= 2;
    }
  return n;
}

TEST(RenderCommand, DrawsTheTrialWithTheReferenceLook) {
  const auto out = test::test_output_dir() / "render_plain.png";
  const test::CommandResult r = test::run_skillcoach("render --task parking --trajectory " +
                                                     quoted(learner_trial_file("render_plain_trial.json")) + " --out " +
                                                     quoted(out) + " --size 800x450");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RgbaImage image = read_png(out);
  EXPECT_EQ(image.width, 800);
  EXPECT_EQ(image.height, 450);
  EXPECT_GT(count_colour(image, 100, 100, 100), 800 * 450 / 3);  // the lot's grey ground
  EXPECT_GT(count_colour(image, 235, 189, 52), 20);              // the car's body
  EXPECT_GT(count_colour(image, 100, 200, 255), 20);             // the goal landmark
}

TEST(RenderCommand, ExpertOverlayAddsTheGhostRibbon) {
  const auto plain = test::test_output_dir() / "render_plain_for_overlay.png";
  const auto overlay = test::test_output_dir() / "render_overlay.png";
  const std::string trial = quoted(learner_trial_file("render_overlay_trial.json"));
  ASSERT_EQ(test::run_skillcoach("render --task parking --trajectory " + trial + " --out " + quoted(plain)).exit_code,
            0);
  const test::CommandResult r = test::run_skillcoach("render --task parking --trajectory " + trial + " --out " +
                                                     quoted(overlay) + " --overlay expert");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::ImageDifference diff = test::compare_images(read_png(overlay), read_png(plain), 8);
  ASSERT_TRUE(diff.same_size);
  EXPECT_GT(diff.differing_fraction(), 0.01);  // the ribbon covers a real part of the lot
}

TEST(RenderCommand, BadTrialFileIsOneLineExitTwo) {
  const auto bad = test::test_output_dir() / "render_bad_trial.json";
  std::ofstream(bad) << R"({"task":"parking","scenario":{"heading0":"north","goal":{"spot":3}},"actions":[]})";
  const test::CommandResult r =
      test::run_skillcoach("render --task parking --trajectory " + quoted(bad) + " --out /tmp/never.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("render_bad_trial.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("heading0"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;  // one line
}

TEST(FreeDriveScreen, HeadlessScreenshotIsDeterministic) {
  const auto a = test::test_output_dir() / "free_drive_a.png";
  const auto b = test::test_output_dir() / "free_drive_b.png";
  const test::CommandResult r =
      test::run_skillcoach("screenshot --screen free_drive --size 1280x720 --out " + quoted(a));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(test::run_skillcoach("screenshot --screen free_drive --size 1280x720 --out " + quoted(b)).exit_code, 0);
  const RgbaImage image = read_png(a);
  const test::ImageDifference diff = test::compare_images(image, read_png(b), 0);
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
  EXPECT_GT(count_colour(image, 235, 189, 52), 50);  // the expert's car is on screen
}

}  // namespace
}  // namespace sc
