// The image-regression harness itself: it must catch a changed scene, honour its tolerances and say how to
// create a missing golden.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/render/bar_chart_image.hpp"
#include "engine/render/gl_context.hpp"
#include "tests/render/primitives_scene.hpp"
#include "tests/support/golden_image.hpp"

namespace sc::test {
namespace {

RgbaImage flat_image(int w, int h, std::uint8_t value) {
  RgbaImage image(w, h);
  for (auto& byte : image.pixels) byte = value;
  return image;
}

TEST(GoldenHarness, DeliberatelyChangedSceneFailsAndWritesActualAndDiff) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), kPrimitivesWidth, kPrimitivesHeight);
  const RgbaImage changed = render_primitives_scene(*context, /*variant=*/1);
  const auto actual_file = test_output_dir() / "render_primitives.actual.png";
  const auto diff_file = test_output_dir() / "render_primitives.diff.png";
  std::filesystem::remove(actual_file);
  std::filesystem::remove(diff_file);
  const auto result = matches_golden(changed, "render/primitives", {}, GoldenMode::compare_only);
  EXPECT_FALSE(result);
  EXPECT_NE(std::string(result.message()).find(diff_file.string()), std::string::npos) << result.message();
  ASSERT_TRUE(std::filesystem::exists(actual_file));
  ASSERT_TRUE(std::filesystem::exists(diff_file));
  // The diff highlights exactly the differing pixels in magenta.
  const RgbaImage diff = read_png(diff_file);
  const RgbaImage golden = read_png(golden_path("render/primitives"));
  const ImageDifference expected = compare_images(changed, golden, 2);
  std::size_t magenta = 0;
  for (int y = 0; y < diff.height; ++y)
    for (int x = 0; x < diff.width; ++x)
      if (diff.at(x, y)[0] == 255 && diff.at(x, y)[1] == 0 && diff.at(x, y)[2] == 255) ++magenta;
  EXPECT_EQ(magenta, expected.differing_pixels);
  EXPECT_GT(expected.differing_pixels, 100u);
}

TEST(GoldenHarness, ChannelToleranceIsTwo) {
  const RgbaImage base = flat_image(100, 100, 100);
  RgbaImage within = base, beyond = base;
  within.at(5, 5)[1] = 102;
  beyond.at(5, 5)[1] = 103;
  EXPECT_EQ(compare_images(within, base, 2).differing_pixels, 0u);
  EXPECT_EQ(compare_images(beyond, base, 2).differing_pixels, 1u);
  EXPECT_EQ(compare_images(beyond, base, 2).max_channel_difference, 3);
}

TEST(GoldenHarness, FailsAboveTwentyFourPixels) {
  // 24 differing pixels pass, 25 fail.
  const auto name = "harness_selftest/flat";
  const RgbaImage golden = flat_image(100, 100, 50);
  const auto dir = test_output_dir() / "golden_root";
  std::filesystem::create_directories(dir / "golden" / "harness_selftest");
  write_png(dir / "golden" / "harness_selftest" / "flat.png", golden);
  const char* saved = std::getenv("SKILLCOACH_TEST_DATA");
  const std::string saved_data = saved != nullptr ? saved : "";
  setenv("SKILLCOACH_TEST_DATA", dir.c_str(), 1);
  RgbaImage actual = golden;
  for (int i = 0; i < 24; ++i) actual.at(i, 0)[0] = 200;
  EXPECT_TRUE(matches_golden(actual, name, {}, GoldenMode::compare_only));
  actual.at(24, 0)[0] = 200;
  EXPECT_FALSE(matches_golden(actual, name, {}, GoldenMode::compare_only));
  EXPECT_FALSE(matches_golden(flat_image(100, 99, 50), name, {}, GoldenMode::compare_only));  // size differs
  setenv("SKILLCOACH_TEST_DATA", saved_data.c_str(), 1);
}

// The limit is far below what a changed word costs: the old limit (0.1 % of the pixels, 921 at 720p) let a
// changed label pass.
TEST(GoldenHarness, AOneWordLabelChangeFails) {
  auto context = create_offscreen_context(offscreen_backend_from_env(), 640, 360);
  BarChartFigure figure;
  figure.title = "Ind. Drills practise the weakest skills";
  figure.width = 640;
  figure.height = 360;
  figure.series = {{"reward", Color::hex(0x4c8bf5)}};
  figure.panels = {{"round 1", "%.2f", {{"Ind. Drills", {-0.4}, {}}}}};
  const RgbaImage before = render_bar_chart_figure(*context, figure);
  figure.title = "Ind. Drills practise the weakest moves";
  const std::size_t changed = compare_images(render_bar_chart_figure(*context, figure), before, 2).differing_pixels;
  EXPECT_GT(changed, 4 * GoldenTolerance{}.max_pixels) << changed;
  EXPECT_EQ(compare_images(render_bar_chart_figure(*context, figure), render_bar_chart_figure(*context, figure), 2)
                .differing_pixels,
            0u);
}

TEST(GoldenHarness, MissingGoldenFailsAndSaysHowToCreateIt) {
  const auto result = matches_golden(flat_image(8, 8, 0), "render/no_such_golden", {}, GoldenMode::compare_only);
  EXPECT_FALSE(result);
  EXPECT_NE(std::string(result.message()).find("SKILLCOACH_UPDATE_GOLDENS=1"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(golden_path("render/no_such_golden")));
}

}  // namespace
}  // namespace sc::test
