#pragma once
// The trainer window (SDL2 + Dear ImGui). Without a display it says so and falls back to the headless demo.
#include <string>

namespace sc {

struct GuiOptions {
  std::string data_dir;  // empty: $XDG_DATA_HOME/skillcoach (or ~/.local/share/skillcoach)
};

// Runs until the window is closed; returns the process exit code.
int run_gui(const GuiOptions& options);

}  // namespace sc
