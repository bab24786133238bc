#pragma once
// Where learner records live by default (XDG base-directory rules); the app's --data-dir overrides it.
#include <filesystem>

namespace sc::records {

// $XDG_DATA_HOME/skillcoach if XDG_DATA_HOME is an absolute path, else $HOME/.local/share/skillcoach.
// Throws sc::InputError if neither is usable.
std::filesystem::path default_data_dir();
// The same rule on given values (null means unset), so it can be tested without touching the environment.
std::filesystem::path data_dir_from_environment(const char* xdg_data_home, const char* home);

}  // namespace sc::records
