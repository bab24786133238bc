#include "app/gui/headless_demo.hpp"

#include <cstdio>

#include "app/gui/navigator.hpp"
#include "app/gui/offscreen_screenshot.hpp"

namespace sc {

std::filesystem::path default_demo_path() { return std::filesystem::current_path() / "skillcoach-demo.png"; }

int run_headless_demo(const std::filesystem::path& out_png) {
  ScreenshotRequest request;
  // The most representative screen this build has: the free-drive lot once it exists, else the start screen.
  for (const char* candidate : {"free_drive", "start"}) {
    if (Navigator::is_available(candidate)) {
      request.screen = candidate;
      break;
    }
  }
  write_png(out_png, render_screen_offscreen(request));
  std::printf("skillcoach: headless demo of the '%s' screen written to %s\n", request.screen.c_str(),
              std::filesystem::absolute(out_png).lexically_normal().c_str());
  std::fflush(stdout);
  return 0;
}

}  // namespace sc
