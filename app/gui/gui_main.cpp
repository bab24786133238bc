// The trainer window: SDL2 + OpenGL 3.3 core + Dear ImGui, screens driven by ScreenHost.
#include "app/gui/gui_main.hpp"

#include <SDL.h>
#include <backends/imgui_impl_sdl.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/gui/headless_demo.hpp"
#include "app/gui/input_script.hpp"
#include "app/gui/input_source.hpp"
#include "app/gui/screen_host.hpp"
#include "app/gui/scripted_input.hpp"
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

int run_window(SdlWindowContext& window, const GuiOptions& options, InputSource& source) {
  AppServices services;
  services.options = options;
  ScreenHost host(window, services, "start", source.max_steps_per_frame());
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
  while (!host.navigator().quit_requested()) {
    source.pump([&](const SDL_Event& event) {
      ImGui_ImplSDL2_ProcessEvent(&event);
      if (event.type == SDL_QUIT) host.navigator().request_quit();
    });
    const double elapsed = source.frame_seconds();
    const float density = window.pixel_density();
    host.imgui().make_current();
    ImGui_ImplSDL2_NewFrame();
    source.feed_imgui_mouse(density);
    FrameInput frame_input = source.poll(window.window(), density);
    frame_input.ui_wants_mouse = ImGui::GetIO().WantCaptureMouse;
    // Only a text field owns the keyboard: with keyboard navigation on, WantCaptureKeyboard is also true
    // whenever a window has focus (every newly shown card takes it), which swallowed Enter on result cards.
    frame_input.ui_wants_keyboard = ImGui::GetIO().WantTextInput;
    host.frame(frame_input, elapsed);
    source.after_frame({host.navigator().current_name(), [&window] { return window.read_rgba(); }});
    window.present();
    if (source.finished()) host.navigator().request_quit();
  }
  return 0;
}

// Runs the loop in `window` and quits SDL afterwards, also when a screen or the script throws.
int run_and_quit(std::unique_ptr<SdlWindowContext> window, const GuiOptions& options, InputSource& source) {
  int code = 0;
  try {
    code = run_window(*window, options, source);
  } catch (...) {
    window.reset();
    SDL_Quit();
    throw;
  }
  window.reset();
  SDL_Quit();
  return code;
}

// A script needs no display: without one it uses SDL's offscreen driver (EGL, llvmpipe), unless the caller
// chose a driver with SDL_VIDEODRIVER. Failing to open a window is an error here, not a demo.
int run_script(const GuiOptions& options) {
  InputScript script = read_input_script(options.script);
  if (!has_display_variable() && std::getenv("SDL_VIDEODRIVER") == nullptr)
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "offscreen");
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0)
    throw std::runtime_error(std::string("SDL cannot start video for the script: ") + SDL_GetError());
  std::unique_ptr<SdlWindowContext> window;
  try {
    window = std::make_unique<SdlWindowContext>("SkillCoach (script)", script.width, script.height);
  } catch (...) {
    SDL_Quit();
    throw;
  }
  ScriptedInput source(std::move(script));
  return run_and_quit(std::move(window), options, source);
}

}  // namespace

int run_gui(const GuiOptions& options) {
  if (!options.script.empty()) return run_script(options);
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
  LiveInputSource source;  // after SDL_Init: it opens the controllers already connected
  return run_and_quit(std::move(window), options, source);
}

}  // namespace sc
