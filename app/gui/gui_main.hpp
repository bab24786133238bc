#pragma once
// The trainer window (SDL2 + Dear ImGui). Without a display it says so and falls back to the headless demo.
// With a script it plays the script instead of reading devices, on SDL's offscreen driver when there is no
// display, and closes when the script ends (InputError for a bad script, ScriptFailure when it fails).
#include <string>

namespace sc {

struct GuiOptions {
  std::string data_dir;  // empty: $XDG_DATA_HOME/skillcoach (or ~/.local/share/skillcoach)
  std::string store;     // non-empty: a class's postgresql:// URL (docs/database.md); data_dir keeps the spill
  std::string script;    // an input script (input_script.hpp) replaces the devices: end-to-end tests
};

// Runs until the window is closed; returns the process exit code.
int run_gui(const GuiOptions& options);

}  // namespace sc
