#include "teaching/records/data_dir.hpp"

#include <cstdlib>

#include "engine/core/error.hpp"

namespace sc::records {

std::filesystem::path data_dir_from_environment(const char* xdg_data_home, const char* home) {
  // The XDG spec says relative values are invalid and must be ignored.
  if (xdg_data_home != nullptr && std::filesystem::path(xdg_data_home).is_absolute())
    return std::filesystem::path(xdg_data_home) / "skillcoach";
  if (home != nullptr && std::filesystem::path(home).is_absolute())
    return std::filesystem::path(home) / ".local" / "share" / "skillcoach";
  throw InputError("data directory", "neither XDG_DATA_HOME nor HOME is set to an absolute path; use --data-dir");
}

std::filesystem::path default_data_dir() {
  return data_dir_from_environment(std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

}  // namespace sc::records
