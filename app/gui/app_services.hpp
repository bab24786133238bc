#pragma once
// State shared by all screens of one run: what the learner chose on the start screen, where records live,
// and the seed every random choice derives from (fixed in screenshots so they are reproducible).
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "app/gui/gui_main.hpp"
#include "engine/core/task_kind.hpp"

namespace sc {

class LearnFlow;  // app/gui/screens/learn_flow.hpp: the trainer's session, shared by its screens

enum class DeviceKind {
  gamepad,         // an SDL game controller (see gamepad_instance_id)
  mouse_joystick,  // the on-screen stick dragged with the mouse (parking)
  keyboard,        // arrow keys (parking)
  mouse_pen,       // mouse or trackpad as a pen (writing)
};

struct DeviceChoice {
  DeviceKind kind = DeviceKind::mouse_joystick;
  int gamepad_instance_id = -1;
  std::string gamepad_name;
};

std::string describe(const DeviceChoice& device);

struct AppServices {
  GuiOptions options;
  std::uint64_t seed = 20221128;  // deterministic by default; the window may pick another per session
  bool headless = false;          // true for screenshots and the demo: no window, no real devices
  TaskKind task = TaskKind::parking;
  DeviceChoice device;
  std::shared_ptr<LearnFlow> learn_flow;  // created by the trainer's first screen
  int screenshot_learner_hand = 0;        // screenshots: the scripted learner's hand (ScriptedRunHooks::hand)
};

}  // namespace sc
