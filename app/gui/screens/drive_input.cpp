#include "app/gui/screens/drive_input.hpp"

#include <array>

#include "engine/input/sdl_input_mapping.hpp"

namespace sc {
namespace {

const GamepadSnapshot* find_pad(const FrameInput& input, int instance_id) {
  for (const auto& pad : input.gamepads)
    if (pad.instance_id == instance_id) return &pad;
  return nullptr;
}

input::GamepadSample sample_of(const GamepadSnapshot& pad) {
  input::GamepadSample s;
  s.left_x = pad.axes[SDL_CONTROLLER_AXIS_LEFTX];
  s.left_y = pad.axes[SDL_CONTROLLER_AXIS_LEFTY];
  s.left_trigger = pad.axes[SDL_CONTROLLER_AXIS_TRIGGERLEFT];
  s.right_trigger = pad.axes[SDL_CONTROLLER_AXIS_TRIGGERRIGHT];
  return s;
}

bool any_button(const GamepadSnapshot& pad) {
  for (bool b : pad.buttons)
    if (b) return true;
  return false;
}

}  // namespace

DriveInput::DriveInput(DeviceChoice& device) : device_(device) {}

void DriveInput::set_joystick_base(Vec2f centre, float radius) { joystick_.set_base({centre.x, centre.y}, radius); }

void DriveInput::update(const FrameInput& input) {
  pause_toggled_ = input.keys_pressed[SDL_SCANCODE_ESCAPE];
  update_gamepad(input);
  update_keyboard(input);
  if (device_.kind == DeviceKind::mouse_joystick)
    update_mouse(input);
  else if (joystick_.grabbed())
    joystick_.release();
  previous_pads_.clear();
  for (const auto& pad : input.gamepads) previous_pads_[pad.instance_id] = pad;
}

bool DriveInput::button_pressed(const GamepadSnapshot& pad, SDL_GameControllerButton button) const {
  const auto before = previous_pads_.find(pad.instance_id);
  const bool was_down = before != previous_pads_.end() && before->second.buttons[button];
  return pad.buttons[button] && !was_down;
}

void DriveInput::update_gamepad(const FrameInput& input) {
  gamepad_action_ = {};
  faulty_ = false;
  if (device_.kind != DeviceKind::gamepad) {
    state_ = DriveInputState::ready;
    return;
  }
  const GamepadSnapshot* pad = find_pad(input, device_.gamepad_instance_id);
  if (pad == nullptr && state_ == DriveInputState::ready && device_.gamepad_instance_id >= 0) {
    state_ = DriveInputState::device_lost;  // ours was unplugged
    lost_name_ = device_.gamepad_name;
    present_when_lost_.clear();
    for (const auto& other : input.gamepads) present_when_lost_.insert(other.instance_id);
  }
  if (pad == nullptr) {
    // Adopt a pad connected since, or one on which the learner presses a button (they picked it up).
    for (const auto& other : input.gamepads) {
      const bool new_pad = !present_when_lost_.contains(other.instance_id);
      const bool woken = any_button(other) && previous_pads_.contains(other.instance_id) &&
                         !any_button(previous_pads_.at(other.instance_id));
      if (new_pad || woken || device_.gamepad_instance_id < 0) {
        device_.gamepad_instance_id = other.instance_id;
        device_.gamepad_name = other.name;
        pad = &other;
        break;
      }
    }
  }
  if (pad == nullptr) {
    if (state_ != DriveInputState::device_lost) state_ = DriveInputState::waiting_for_gamepad;
    return;
  }
  state_ = DriveInputState::ready;
  const input::InputReading reading = input::map_gamepad(sample_of(*pad), config_);
  gamepad_action_ = reading.action;
  faulty_ = reading.faulty;
  if (button_pressed(*pad, SDL_CONTROLLER_BUTTON_START)) pause_toggled_ = !pause_toggled_;
}

void DriveInput::update_keyboard(const FrameInput& input) {
  if (input.ui_wants_keyboard) {
    keyboard_.release_all();  // typing a seed must not drive the car
    return;
  }
  for (SDL_Scancode code : {SDL_SCANCODE_UP, SDL_SCANCODE_DOWN, SDL_SCANCODE_LEFT, SDL_SCANCODE_RIGHT, SDL_SCANCODE_W,
                            SDL_SCANCODE_A, SDL_SCANCODE_S, SDL_SCANCODE_D, SDL_SCANCODE_LSHIFT, SDL_SCANCODE_RSHIFT})
    if (const auto key = input::drive_key_for_scancode(code)) keyboard_.set_pressed(*key, input.keys_down[code]);
}

void DriveInput::update_mouse(const FrameInput& input) {
  const input::Vec2 pointer{input.mouse_pixels.x, input.mouse_pixels.y};
  if (input.mouse_pressed[0] && input.mouse_inside && !input.ui_wants_mouse) joystick_.press(pointer);
  if (joystick_.grabbed()) {
    if (!input.mouse_down[0] || input.mouse_released[0])
      joystick_.release();
    else if (input.mouse_inside)
      joystick_.drag(pointer);
  }
}

input::DriveAction DriveInput::action() const {
  if (state_ != DriveInputState::ready) return {};
  switch (device_.kind) {
    case DeviceKind::gamepad:
      return gamepad_action_;
    case DeviceKind::keyboard:
      return keyboard_.action();
    case DeviceKind::mouse_joystick:
      return joystick_.action();
    case DeviceKind::mouse_pen:
      return {};
  }
  return {};
}

std::string DriveInput::status() const {
  switch (state_) {
    case DriveInputState::device_lost:
      return "Gamepad \"" + lost_name_ + "\" disconnected - plug it back in or press a button on another pad.";
    case DriveInputState::waiting_for_gamepad:
      return "Waiting for a gamepad - plug one in.";
    case DriveInputState::ready:
      break;
  }
  if (faulty_) return describe(device_) + " (sent invalid values: treated as neutral)";
  return describe(device_);
}

}  // namespace sc
