#include "tests/support/scratch_files.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace sc::test {

std::filesystem::path scratch_path(std::string_view group, std::string_view name) {
  const char* dir = std::getenv("SKILLCOACH_TEST_OUTPUT");
  const auto base = std::filesystem::path(dir != nullptr ? dir : "/tmp") / group;
  std::filesystem::create_directories(base);
  return base / name;
}

std::filesystem::path fresh_scratch_dir(std::string_view name) {
  const char* dir = std::getenv("SKILLCOACH_TEST_OUTPUT");
  const auto path = std::filesystem::path(dir != nullptr ? dir : "/tmp") / name;
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& file, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

int temporaries_left_of(const std::filesystem::path& file) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(file.parent_path())) {
    const std::string name = entry.path().filename().string();
    count += name.rfind(file.filename().string(), 0) == 0 && entry.path().extension() == ".tmp" ? 1 : 0;
  }
  return count;
}

}  // namespace sc::test
