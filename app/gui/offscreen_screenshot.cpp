#include "app/gui/offscreen_screenshot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <charconv>

#include "app/gui/screen_host.hpp"
#include "engine/core/error.hpp"

namespace sc {

RgbaImage render_screen_offscreen(const ScreenshotRequest& request) {
  if (!Navigator::is_available(request.screen))
    throw InputError("--screen " + request.screen, "unknown screen (registered: " + registered_screen_names() + ")");
  auto context = create_offscreen_context_from_env(request.width, request.height);
  AppServices services;
  services.headless = true;
  services.task = request.task;
  services.screenshot_learner_hand = request.learner_hand;
  if (request.task == TaskKind::writing) services.device.kind = DeviceKind::mouse_pen;
  ScreenHost host(*context, services, request.screen);
  FrameInput input;  // no devices, nothing pressed
  if (request.mouse) {
    input.mouse_inside = true;
    input.mouse_pixels = {request.mouse->first, request.mouse->second};
  }
  for (int i = 0; i < std::max(2, request.frames); ++i) {
    host.imgui().make_current();
    ImGui::GetIO().MousePos =
        request.mouse ? ImVec2(request.mouse->first, request.mouse->second) : ImVec2(-FLT_MAX, -FLT_MAX);
    host.frame(input, ScreenHost::kSimulationStep);
    context->present();
  }
  return context->read_rgba();
}

std::pair<float, float> parse_point(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  int x = 0, y = 0;
  const bool ok =
      comma != std::string::npos && std::from_chars(text.data(), text.data() + comma, x).ptr == text.data() + comma &&
      std::from_chars(text.data() + comma + 1, text.data() + text.size(), y).ptr == text.data() + text.size();
  if (!ok || x < 0 || y < 0 || x > 8192 || y > 8192)
    throw InputError(option + " " + text, "expected X,Y in framebuffer pixels with each in 0..8192, e.g. 640,360");
  return {static_cast<float>(x), static_cast<float>(y)};
}

std::pair<int, int> parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find('x');
  int w = 0, h = 0;
  const bool ok = x != std::string::npos && std::from_chars(text.data(), text.data() + x, w).ptr == text.data() + x &&
                  std::from_chars(text.data() + x + 1, text.data() + text.size(), h).ptr == text.data() + text.size();
  if (!ok || w < 64 || h < 64 || w > 8192 || h > 8192)
    throw InputError(option + " " + text, "expected WIDTHxHEIGHT with each side in 64..8192, e.g. 1280x720");
  return {w, h};
}

}  // namespace sc
