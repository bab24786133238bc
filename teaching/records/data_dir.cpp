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

std::filesystem::path data_dir_of_store(const std::string& store) {
  if (store.empty()) return default_data_dir();
  if (store.find("://") != std::string::npos)
    throw InputError(
        store, "is a URL of an unknown kind (a store is a data directory, its skillcoach.db, or a postgresql:// URL)");
  const std::filesystem::path path(store);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return path;
  if (path.filename() == "skillcoach.db") return path.has_parent_path() ? path.parent_path() : ".";
  if (std::filesystem::exists(path, ec))
    throw InputError(store, "is neither a data directory nor a skillcoach.db file");
  return path;  // a data directory still to be created (writers create it; readers report it missing)
}

std::filesystem::path default_data_dir() {
  return data_dir_from_environment(std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

}  // namespace sc::records
