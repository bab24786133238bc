#include "engine/render/rgba_image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <system_error>

#include "engine/core/error.hpp"

namespace sc {

void write_png(const std::filesystem::path& file, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw InputError(file.string(), "cannot write an empty or inconsistent image");
  if (file.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
  }
  const int ok = stbi_write_png(file.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4);
  if (ok == 0) throw InputError(file.string(), "could not write PNG (folder missing or not writable?)");
}

RgbaImage read_png(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), "PNG file not found");
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(file.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) throw InputError(file.string(), std::string("not a readable PNG: ") + stbi_failure_reason());
  RgbaImage image(w, h);
  std::memcpy(image.pixels.data(), data, image.pixels.size());
  stbi_image_free(data);
  return image;
}

}  // namespace sc
