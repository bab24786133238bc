#pragma once
// Everything a screen may read about the user's devices in one frame, as plain data: the window fills it
// from SDL, headless runs (screenshots, scripted end-to-end tests) fill it themselves. Positions are in
// framebuffer pixels with a top-left origin, like ImGui and Camera2D.
#include <SDL.h>

#include <array>
#include <string>
#include <vector>

#include "engine/render/draw_types.hpp"

namespace sc {

struct GamepadSnapshot {
  int instance_id = -1;  // SDL joystick instance id, stable while connected
  std::string name;
  // SDL_GameControllerAxis order, each in [-1, 1] (triggers in [0, 1]).
  std::array<float, SDL_CONTROLLER_AXIS_MAX> axes{};
  // SDL_GameControllerButton order.
  std::array<bool, SDL_CONTROLLER_BUTTON_MAX> buttons{};
};

// A mouse motion or button event between two frames. A pen trace needs the positions between frames too
// (the writing task samples the mouse on every motion event as well as every frame).
struct MouseEvent {
  double time_seconds = 0;  // the event's SDL time stamp (ms since SDL_Init) / 1000
  Vec2f pixels;             // framebuffer pixels, top-left origin
  bool left_down = false;   // the left button's state after the event
};

struct FrameInput {
  bool mouse_inside = false;  // false: mouse_pixels is meaningless (headless or outside the window)
  Vec2f mouse_pixels;
  std::array<bool, 3> mouse_down{};     // left, right, middle
  std::array<bool, 3> mouse_pressed{};  // went down since the previous frame
  std::array<bool, 3> mouse_released{};
  float wheel = 0;
  std::array<bool, SDL_NUM_SCANCODES> keys_down{};
  std::array<bool, SDL_NUM_SCANCODES> keys_pressed{};
  std::vector<GamepadSnapshot> gamepads;  // connected game controllers, in connection order
  bool ui_wants_mouse = false;            // ImGui is using the mouse (hovering a window): scene input should ignore it
  bool ui_wants_keyboard = false;         // ImGui has keyboard focus (text field)
  std::vector<MouseEvent> mouse_events;   // motion/button events since the previous frame, in order
  double time_seconds = 0;                // when this frame was polled, on the clock of mouse_events (0 headless)

  // The same input with every "pressed/released" edge cleared: given to the 2nd and later simulation steps
  // of a frame so an edge acts once.
  FrameInput without_edges() const {
    FrameInput copy = *this;
    copy.mouse_pressed = {};
    copy.mouse_released = {};
    copy.keys_pressed = {};
    copy.wheel = 0;
    copy.mouse_events.clear();
    return copy;
  }
};

}  // namespace sc
