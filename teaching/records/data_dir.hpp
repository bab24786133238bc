#pragma once
// Where learner records live by default (XDG base-directory rules); the app's --data-dir overrides it.
#include <filesystem>
#include <string>

namespace sc::records {

// $XDG_DATA_HOME/skillcoach if XDG_DATA_HOME is an absolute path, else $HOME/.local/share/skillcoach.
// Throws sc::InputError if neither is usable.
std::filesystem::path default_data_dir();
// The same rule on given values (null means unset), so it can be tested without touching the environment.
std::filesystem::path data_dir_from_environment(const char* xdg_data_home, const char* home);
// The data directory named by a `--store` option: a directory, or the skillcoach.db file inside one; empty
// means default_data_dir(). Throws sc::InputError naming the value for a URL (open_record_store.hpp opens
// postgresql:// ones) or a file of another name.
std::filesystem::path data_dir_of_store(const std::string& store);

}  // namespace sc::records
