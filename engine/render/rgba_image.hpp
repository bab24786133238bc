#pragma once
// An 8-bit RGBA image with rows stored top to bottom, and PNG input/output (stb).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sc {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4, top row first

  RgbaImage() = default;
  RgbaImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* at(int x, int y) { return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
  const std::uint8_t* at(int x, int y) const { return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
};

// Writes a PNG, creating parent folders; throws InputError naming the file on failure.
void write_png(const std::filesystem::path& file, const RgbaImage& image);
// Reads any PNG as RGBA; throws InputError naming the file when missing or undecodable.
RgbaImage read_png(const std::filesystem::path& file);

}  // namespace sc
