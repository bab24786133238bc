#include "engine/core/asset_paths.hpp"

#include <cstdlib>
#include <system_error>

#include "engine/core/error.hpp"

namespace sc {
namespace {

std::filesystem::path executable_dir() {
  std::error_code ec;
  auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path{} : exe.parent_path();
}

std::filesystem::path locate(const char* env_var, const char* folder) {
  if (const char* env = std::getenv(env_var); env != nullptr && *env != '\0') return env;
  if (auto exe = executable_dir(); !exe.empty()) {
    auto installed = exe / ".." / "share" / "skillcoach" / folder;
    if (std::filesystem::is_directory(installed)) return installed.lexically_normal();
  }
  return std::filesystem::path(SKILLCOACH_SOURCE_DIR) / folder;
}

std::filesystem::path existing(const std::filesystem::path& root, std::string_view relative, const char* what) {
  auto path = root / relative;
  if (!std::filesystem::exists(path))
    throw InputError(path.string(), std::string(what) + " not found (set SKILLCOACH_ASSET_DIR/SKILLCOACH_SHADER_DIR?)");
  return path;
}

}  // namespace

std::filesystem::path asset_dir() { return locate("SKILLCOACH_ASSET_DIR", "assets"); }
std::filesystem::path shader_dir() { return locate("SKILLCOACH_SHADER_DIR", "shaders"); }

std::filesystem::path asset_path(std::string_view relative) { return existing(asset_dir(), relative, "asset"); }
std::filesystem::path shader_path(std::string_view relative) { return existing(shader_dir(), relative, "shader"); }

}  // namespace sc
