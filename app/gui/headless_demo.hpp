#pragma once
// The headless demo: what `skillcoach` shows when there is no display. Renders a representative screen
// offscreen, writes it as a PNG and prints the path.
#include <filesystem>

namespace sc {

// Returns the process exit code (0). Throws InputError when no offscreen GL context or asset is available.
int run_headless_demo(const std::filesystem::path& out_png);

// skillcoach-demo.png in the current directory.
std::filesystem::path default_demo_path();

}  // namespace sc
