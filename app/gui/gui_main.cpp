// The trainer window: SDL2 + OpenGL 3.3 core + Dear ImGui, screens driven by ScreenHost.
#include "app/gui/gui_main.hpp"

#include <SDL.h>
#include <backends/imgui_impl_sdl.h>

#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "app/gui/headless_demo.hpp"
#include "app/gui/screen_host.hpp"
#include "app/gui/sdl_input.hpp"
#include "engine/core/error.hpp"
#include "engine/render/sdl_window_context.hpp"

namespace sc {
namespace {

bool has_display_variable() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && *value != '\0') return true;
  }
  return false;
}

int fall_back_to_demo(const std::string& reason) {
  std::printf("skillcoach: %s; running the headless demo instead\n", one_line(reason).c_str());
  std::fflush(stdout);
  return run_headless_demo(default_demo_path());
}

// ImGui's SDL backend reports window points; ImGui runs in framebuffer pixels here (see ImGuiLayer).
void mouse_to_pixels(float pixel_density) {
  ImGuiIO& io = ImGui::GetIO();
  if (io.MousePos.x != -FLT_MAX && io.MousePos.y != -FLT_MAX)
    io.MousePos = ImVec2(io.MousePos.x * pixel_density, io.MousePos.y * pixel_density);
}

int run_window(SdlWindowContext& window, const GuiOptions& options) {
  AppServices services;
  services.options = options;
  ScreenHost host(window, services, "start");
  host.imgui().make_current();
  if (!ImGui_ImplSDL2_InitForOpenGL(window.window(), window.sdl_gl_context()))
    throw InputError("SDL window", "ImGui SDL2 backend failed to start");
  // Shut the platform backend down before the ImGui context goes away, also when a screen throws.
  struct PlatformBackendGuard {
    ImGuiLayer& imgui;
    ~PlatformBackendGuard() {
      imgui.make_current();
      ImGui_ImplSDL2_Shutdown();
    }
  } guard{host.imgui()};
  SdlInput input;
  Uint64 previous = SDL_GetPerformanceCounter();
  const double ticks_per_second = static_cast<double>(SDL_GetPerformanceFrequency());
  while (!host.navigator().quit_requested()) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
      ImGui_ImplSDL2_ProcessEvent(&event);
      input.handle_event(event);
      if (event.type == SDL_QUIT) host.navigator().request_quit();
    }
    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = static_cast<double>(now - previous) / ticks_per_second;
    previous = now;
    const float density = window.pixel_density();
    host.imgui().make_current();
    ImGui_ImplSDL2_NewFrame();
    mouse_to_pixels(density);
    FrameInput frame_input = input.poll(window.window(), density);
    frame_input.ui_wants_mouse = ImGui::GetIO().WantCaptureMouse;
    // Only a text field owns the keyboard: with keyboard navigation on, WantCaptureKeyboard is also true
    // whenever a window has focus (every newly shown card takes it), which swallowed Enter on result cards.
    frame_input.ui_wants_keyboard = ImGui::GetIO().WantTextInput;
    host.frame(frame_input, elapsed);
    window.present();
  }
  return 0;
}

}  // namespace

int run_gui(const GuiOptions& options) {
  if (!has_display_variable()) return fall_back_to_demo("no display found (DISPLAY and WAYLAND_DISPLAY are unset)");
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER | SDL_INIT_EVENTS) != 0)
    return fall_back_to_demo(std::string("SDL cannot open the display: ") + SDL_GetError());
  std::unique_ptr<SdlWindowContext> window;
  try {
    window = std::make_unique<SdlWindowContext>("SkillCoach", 1280, 720);
  } catch (const InputError& error) {
    SDL_Quit();
    return fall_back_to_demo(error.what());
  }
  int code = 0;
  try {
    code = run_window(*window, options);
  } catch (...) {
    window.reset();
    SDL_Quit();
    throw;
  }
  window.reset();
  SDL_Quit();
  return code;
}

}  // namespace sc
