#pragma once
// Screens of the trainer register themselves, like Box2D's samples: a file app/gui/screens/<name>_screen.cpp
// defines a Screen subclass and one
//   static const sc::ScreenRegistration kFreeDriveScreenRegistration{{"free_drive", "Free drive",
//       [](sc::AppServices& services) { return std::make_unique<FreeDriveScreen>(services); }}};
// and the navigator, `skillcoach screenshot --screen free_drive` and the golden tests all find it by name.
//
// A screen's update() runs at the fixed simulation rate (engine/core/fixed_step_clock); draw() runs once per
// displayed frame with `ui.alpha` to interpolate between the last two simulation states. In draw(), world
// scenes go through ui.renderer (set a Camera2D first) and widgets/text through ImGui.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/gui/app_services.hpp"
#include "app/gui/frame_input.hpp"
#include "engine/render/draw_types.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

class Navigator;

struct UiContext {
  Renderer2D& renderer;
  const UiFonts& fonts;
  float ui_scale;  // 1 at 720 px tall, 3 at 4K: multiply hand-picked pixel sizes by it
  int width;       // framebuffer pixels
  int height;
  double alpha;             // interpolation between the previous and current simulation state, [0, 1)
  double time_seconds;      // simulation time since the screen was entered
  const FrameInput& input;  // this frame's input (edges included)
  Navigator& navigator;
  AppServices& services;
};

class Screen {
 public:
  virtual ~Screen() = default;
  // Called when the navigator makes this screen current (also the first time).
  virtual void on_enter() {}
  // One fixed simulation step of `dt` seconds.
  virtual void update(const FrameInput& input, double dt) {
    (void)input;
    (void)dt;
  }
  virtual void draw(UiContext& ui) = 0;
  virtual Color background() const { return Color::hex(0x14181f); }
};

using ScreenFactory = std::function<std::unique_ptr<Screen>(AppServices&)>;

struct ScreenSpec {
  std::string name;   // id used by the navigator and `skillcoach screenshot --screen`
  std::string title;  // human-readable
  ScreenFactory create;
};

class ScreenRegistration {
 public:
  explicit ScreenRegistration(ScreenSpec spec);
};

// All registered screens sorted by name; find_screen returns nullptr for an unknown name.
std::vector<ScreenSpec> registered_screens();
const ScreenSpec* find_screen(std::string_view name);
// "start, free_drive, ..." for error messages.
std::string registered_screen_names();

}  // namespace sc
