// skillcoach screenshot: render any registered screen offscreen into a PNG, deterministically.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "app/gui/offscreen_screenshot.hpp"
#include "app/gui/screen.hpp"

namespace sc::cli {
namespace {

struct ScreenshotOptions {
  std::string screen = "start";
  std::string out;
  std::string size = "1280x720";
  int frames = 3;
  TaskKind task = TaskKind::parking;
  int learner_hand = 0;
  std::string mouse;  // "X,Y", empty: outside the window
};

CommandRunner setup_screenshot(CLI::App& sub) {
  auto options = std::make_shared<ScreenshotOptions>();
  sub.add_option("--screen", options->screen, "Registered screen to render")->capture_default_str();
  sub.add_option("--out", options->out, "PNG file to write")->required();
  sub.add_option("--size", options->size, "Framebuffer size WIDTHxHEIGHT")->capture_default_str();
  sub.add_option("--frames", options->frames, "Frames to render before capturing (at least 2)")
      ->capture_default_str()
      ->check(CLI::Range(2, 600));
  add_task_option(sub, options->task, "Task the trainer's screens show (default parking)");
  sub.add_option("--learner-hand", options->learner_hand,
                 "Writing: the scripted learner writes its tests in this Omniglot drawer's letters (0: the guide's)")
      ->capture_default_str()
      ->check(CLI::Range(0, 15));
  sub.add_option("--mouse", options->mouse,
                 "Rest the mouse at X,Y (framebuffer pixels from the top left) to capture what hovering shows");
  return [options] {
    ScreenshotRequest request;
    request.screen = options->screen;
    std::tie(request.width, request.height) = parse_size(options->size, "--size");
    request.frames = options->frames;
    request.task = options->task;
    request.learner_hand = options->learner_hand;
    if (!options->mouse.empty()) request.mouse = parse_point(options->mouse, "--mouse");
    write_png(options->out, render_screen_offscreen(request));
    std::printf("%s\n", options->out.c_str());
    return 0;
  };
}

const CommandRegistration kScreenshotCommandRegistration{
    {"screenshot", "Render a screen offscreen to a PNG (SKILLCOACH_GL=osmesa|egl picks the backend)",
     "skillcoach screenshot --screen start --out start.png --size 1280x720", setup_screenshot}};

}  // namespace
}  // namespace sc::cli
