#pragma once
// Image-regression checks against golden PNGs in tests/golden/. See tests/README.md for the workflow.
//
//   EXPECT_TRUE(sc::test::matches_golden(image, "render/primitives"));
//
// compares with $SKILLCOACH_TEST_DATA/golden/render/primitives.png. A pixel differs when any channel differs
// by more than 2; the check fails when more than 24 pixels differ (the measured residual is 0 on OSMesa and
// EGL for every golden, docs/development.md; a one-word label change differs in hundreds), and then writes
// render_primitives.actual.png and render_primitives.diff.png into $SKILLCOACH_TEST_OUTPUT and names them in
// the failure message. With SKILLCOACH_UPDATE_GOLDENS=1 the golden is (re)written instead and the check passes.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "engine/render/rgba_image.hpp"

namespace sc::test {

struct ImageDifference {
  bool same_size = false;
  std::size_t differing_pixels = 0;
  std::size_t total_pixels = 0;
  int max_channel_difference = 0;
  RgbaImage highlight;  // the expected image dimmed to grey, differing pixels in magenta (when same_size)

  double differing_fraction() const {
    return total_pixels == 0 ? 1.0 : static_cast<double>(differing_pixels) / static_cast<double>(total_pixels);
  }
};

struct GoldenTolerance {
  int channel = 2;              // a pixel differs if any channel differs by more than this
  std::size_t max_pixels = 24;  // fail if more pixels than this differ
};

enum class GoldenMode {
  from_environment,  // update when SKILLCOACH_UPDATE_GOLDENS=1, else compare
  compare_only,      // never write the golden (for tests of the harness itself)
};

ImageDifference compare_images(const RgbaImage& actual, const RgbaImage& expected, int channel_tolerance);

// tests/golden/<name>.png under $SKILLCOACH_TEST_DATA.
std::filesystem::path golden_path(std::string_view name);
// $SKILLCOACH_TEST_OUTPUT (created if needed).
std::filesystem::path test_output_dir();

::testing::AssertionResult matches_golden(const RgbaImage& actual, std::string_view name,
                                          GoldenTolerance tolerance = {},
                                          GoldenMode mode = GoldenMode::from_environment);

}  // namespace sc::test
