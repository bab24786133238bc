#include "tests/support/golden_image.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sc::test {
namespace {

std::filesystem::path env_dir(const char* variable) {
  const char* value = std::getenv(variable);
  if (value == nullptr || *value == '\0')
    throw std::runtime_error(std::string(variable) + " is not set (run the test through ctest)");
  return value;
}

bool update_requested() {
  const char* value = std::getenv("SKILLCOACH_UPDATE_GOLDENS");
  return value != nullptr && std::string_view(value) == "1";
}

std::string flat_name(std::string_view name) {
  std::string flat(name);
  std::replace(flat.begin(), flat.end(), '/', '_');
  return flat;
}

}  // namespace

std::filesystem::path golden_path(std::string_view name) {
  return env_dir("SKILLCOACH_TEST_DATA") / "golden" / (std::string(name) + ".png");
}

std::filesystem::path test_output_dir() {
  auto dir = env_dir("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::create_directories(dir);
  return dir;
}

ImageDifference compare_images(const RgbaImage& actual, const RgbaImage& expected, int channel_tolerance) {
  ImageDifference result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  result.total_pixels = static_cast<std::size_t>(std::max(0, expected.width)) * std::max(0, expected.height);
  if (!result.same_size) {
    result.differing_pixels = result.total_pixels;
    return result;
  }
  result.highlight = RgbaImage(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* a = actual.at(x, y);
      const std::uint8_t* e = expected.at(x, y);
      int worst = 0;
      for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int{a[c]} - int{e[c]}));
      result.max_channel_difference = std::max(result.max_channel_difference, worst);
      std::uint8_t* h = result.highlight.at(x, y);
      if (worst > channel_tolerance) {
        ++result.differing_pixels;
        h[0] = 255, h[1] = 0, h[2] = 255, h[3] = 255;
      } else {
        const auto grey = static_cast<std::uint8_t>((int{e[0]} + int{e[1]} + int{e[2]}) / 3 / 3 + 40);
        h[0] = h[1] = h[2] = grey, h[3] = 255;
      }
    }
  }
  return result;
}

::testing::AssertionResult matches_golden(const RgbaImage& actual, std::string_view name, GoldenTolerance tolerance,
                                          GoldenMode mode) {
  const auto golden = golden_path(name);
  if (mode == GoldenMode::from_environment && update_requested()) {
    write_png(golden, actual);
    std::printf("[golden] wrote %s\n", golden.c_str());
    return ::testing::AssertionSuccess() << "golden updated: " << golden.string();
  }
  if (!std::filesystem::exists(golden))
    return ::testing::AssertionFailure()
           << "golden image " << golden.string()
           << " does not exist; create it with SKILLCOACH_UPDATE_GOLDENS=1 ctest -R <test>"
              " and review the PNG before committing it";
  const RgbaImage expected = read_png(golden);
  const ImageDifference diff = compare_images(actual, expected, tolerance.channel);
  // The measured residual, passing or not (`ctest -L render -V | grep residual`: docs/development.md).
  std::printf("[golden] residual %s: %zu pixels differ by more than %d (max channel difference %d)\n",
              std::string(name).c_str(), diff.differing_pixels, tolerance.channel, diff.max_channel_difference);
  if (diff.same_size && diff.differing_pixels <= tolerance.max_pixels) return ::testing::AssertionSuccess();

  const auto out = test_output_dir();
  const auto actual_file = out / (flat_name(name) + ".actual.png");
  write_png(actual_file, actual);
  std::ostringstream message;
  message << "image differs from golden " << golden.string() << ": ";
  if (!diff.same_size) {
    message << "size " << actual.width << "x" << actual.height << " vs golden " << expected.width << "x"
            << expected.height;
  } else {
    const auto diff_file = out / (flat_name(name) + ".diff.png");
    write_png(diff_file, diff.highlight);
    message << diff.differing_pixels << " of " << diff.total_pixels << " pixels (limit " << tolerance.max_pixels
            << ") differ by more than " << tolerance.channel << " (max channel difference "
            << diff.max_channel_difference << "); diff: " << diff_file.string();
  }
  message << "; actual: " << actual_file.string();
  std::printf("[golden] actual: %s\n", actual_file.c_str());
  return ::testing::AssertionFailure() << message.str();
}

}  // namespace sc::test
