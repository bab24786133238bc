#pragma once
// Renders a registered screen without a window, deterministically: offscreen GL context (SKILLCOACH_GL, else
// OSMesa then EGL), fixed seed, fixed 1/60 s frames, no devices, the mouse outside or resting at a given point
// (what hovering shows, e.g. a tooltip), never pressed. ImGui's first frame differs
// from later ones (window sizes settle), so at least 2 frames are rendered before the capture.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "app/gui/app_services.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

struct ScreenshotRequest {
  std::string screen = "start";
  int width = 1280;
  int height = 720;
  int frames = 3;                     // clamped to >= 2
  TaskKind task = TaskKind::parking;  // the task the trainer's screens show
  int learner_hand = 0;               // writing: the scripted learner's tests in this Omniglot drawer's letters
  std::optional<std::pair<float, float>> mouse;  // framebuffer pixels from the top left; none: outside the window
};

RgbaImage render_screen_offscreen(const ScreenshotRequest& request);

// "1280x720" -> {1280, 720}; throws InputError naming `option` for anything else (or sizes outside 64..8192).
std::pair<int, int> parse_size(const std::string& text, const std::string& option);
// "640,360" -> {640, 360}; throws InputError naming `option` for anything else (or coordinates outside 0..8192).
std::pair<float, float> parse_point(const std::string& text, const std::string& option);

}  // namespace sc
