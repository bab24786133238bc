// A PNG that cannot be written completely is an error, never a truncated file reported as written: a
// device that is always full, and a file-size limit standing in for a full disk (no root needed).
#include "engine/render/rgba_image.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

// Noise does not compress, so the PNG is about as large as the pixels (~64 kB).
RgbaImage noise_image() {
  RgbaImage image(128, 128);
  std::uint32_t state = 12345;
  for (auto& byte : image.pixels) {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  return image;
}

std::string error_of(const std::filesystem::path& file, const RgbaImage& image) {
  try {
    write_png(file, image);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RgbaImage, WritingToAFullDeviceFails) {
  const auto message = error_of("/dev/full", noise_image());
  EXPECT_EQ(message.rfind("/dev/full: write failed", 0), 0u) << message;
}

TEST(RgbaImage, AFileSizeLimitFailsTheWriteAndLeavesNoPartialFile) {
  const auto dir = test::fresh_scratch_dir("rgba_image_fsize");
  const auto file = dir / "picture.png";
  const pid_t pid = fork();
  if (pid == 0) {
    signal(SIGXFSZ, SIG_IGN);  // as the program does: the write fails with EFBIG instead of killing us
    rlimit limit{16 * 1024, RLIM_INFINITY};
    setrlimit(RLIMIT_FSIZE, &limit);
    const auto message = error_of(file, noise_image());
    _exit(message.find("write failed") != std::string::npos ? 0 : 1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the write past the limit was not reported";
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_EQ(test::temporaries_left_of(file), 0);
  write_png(file, noise_image());  // without the limit it is written whole
  EXPECT_EQ(read_png(file).pixels, noise_image().pixels);
}

}  // namespace
}  // namespace sc
