#include "engine/render/rgba_image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <string>
#include <system_error>

#include "engine/core/atomic_file.hpp"
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
  // Encoded in memory, then written by our own writer: stb's file writer ignores fwrite/fclose errors, so a
  // full disk left a truncated PNG and success; write_output_file checks every write and leaves no partial
  // file behind.
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  const int ok =
      stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.pixels.data(), image.width * 4);
  if (ok == 0) throw InputError(file.string(), "could not encode the PNG");
  write_output_file(file, bytes);
}

RgbaImage read_png(const std::filesystem::path& file) {
  std::error_code ec;  // non-throwing: an unsearchable directory is one line
  if (!std::filesystem::exists(file, ec)) throw InputError(file.string(), "PNG file not found");
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(file.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) throw InputError(file.string(), std::string("not a readable PNG: ") + stbi_failure_reason());
  RgbaImage image(w, h);
  std::memcpy(image.pixels.data(), data, image.pixels.size());
  stbi_image_free(data);
  return image;
}

}  // namespace sc
