#include "app/gui/input_source.hpp"

#include <imgui.h>

#include <cfloat>

#include "app/gui/screen_host.hpp"

namespace sc {

int InputSource::max_steps_per_frame() const { return ScreenHost::kMaxStepsPerFrame; }

void LiveInputSource::pump(const std::function<void(const SDL_Event&)>& deliver) {
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    deliver(event);
    input_.handle_event(event);
  }
}

// The first frame advances nothing: the time before it went into start-up (fonts, the GL context).
double LiveInputSource::frame_seconds() {
  const Uint64 now = SDL_GetPerformanceCounter();
  const double elapsed =
      previous_ == 0 ? 0.0 : static_cast<double>(now - previous_) / static_cast<double>(SDL_GetPerformanceFrequency());
  previous_ = now;
  return elapsed;
}

// ImGui's SDL backend reports window points; ImGui runs in framebuffer pixels here (see ImGuiLayer).
void LiveInputSource::feed_imgui_mouse(float pixel_density) {
  ImGuiIO& io = ImGui::GetIO();
  if (io.MousePos.x != -FLT_MAX && io.MousePos.y != -FLT_MAX)
    io.MousePos = ImVec2(io.MousePos.x * pixel_density, io.MousePos.y * pixel_density);
}

FrameInput LiveInputSource::poll(SDL_Window* window, float pixel_density) { return input_.poll(window, pixel_density); }

}  // namespace sc
