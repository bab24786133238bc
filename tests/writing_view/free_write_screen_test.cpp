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
#include "tests/support/run_skillcoach.hpp"

namespace sc::test {
namespace {

TEST(FreeWriteScreen, HeadlessScreenshotMatchesGoldenAndIsDeterministic) {
  const auto a = test_output_dir() / "free_write_a.png", b = test_output_dir() / "free_write_b.png";
  const CommandResult first =
      run_skillcoach("screenshot --screen free_write --size 1280x720 --out '" + a.string() + "'");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const CommandResult second =
      run_skillcoach("screenshot --screen free_write --size 1280x720 --frames 5 --out '" + b.string() + "'");
  ASSERT_EQ(second.exit_code, 0) << second.output;
  const RgbaImage image = read_png(a);
  EXPECT_EQ(compare_images(image, read_png(b), 0).differing_pixels, 0u);
  EXPECT_TRUE(matches_golden(image, "writing/free_write_screen"));
}

}  // namespace
}  // namespace sc::test
