#include "engine/core/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <functional>
#include <string>
#include <system_error>
#include <thread>

#include "engine/core/error.hpp"

namespace sc {

std::filesystem::path temporary_sibling(const std::filesystem::path& file) {
  const std::size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "." + std::string.
  std::string suffix(1, '.');
  suffix += std::to_string(::getpid());
  suffix += '-';
  suffix += std::to_string(thread % 1000000);
  suffix += ".tmp";
  auto tmp = file;
  tmp += suffix;
  return tmp;
}

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
  const std::filesystem::path tmp = temporary_sibling(file);
  auto discard = [&tmp] {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(file.string(), "cannot be written");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      discard();
      throw InputError(file.string(), "write failed (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    discard();
    throw InputError(file.string(), "cannot be replaced: " + ec.message());
  }
}

}  // namespace sc
