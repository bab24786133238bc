#pragma once
// The driving input of the screens that drive the car (free drive, the trainer's trials), read from the
// frame's input snapshot (FrameInput) with the SDL-free device logic of engine/input: gamepad axes through
// map_gamepad (dead zones, disc->square), the on-screen VirtualJoystick dragged with the mouse, and
// KeyboardDrive (arrows/WASD by scancode).
// Gamepad hot-plug follows DeviceManager's rules: when the pad in use disappears the drive must pause
// (DeviceLost) until a gamepad is connected or a button is pressed on another connected pad, which is
// then adopted (the start screen's DeviceChoice is updated).
#include <map>
#include <set>
#include <string>

#include "app/gui/app_services.hpp"
#include "app/gui/frame_input.hpp"
#include "engine/input/gamepad_mapping.hpp"
#include "engine/input/keyboard_drive.hpp"
#include "engine/input/virtual_joystick.hpp"

namespace sc {

enum class DriveInputState { ready, waiting_for_gamepad, device_lost };

class DriveInput {
 public:
  explicit DriveInput(DeviceChoice& device);

  // Reads one fixed-step input. Call once per Screen::update().
  void update(const FrameInput& input);
  // Where the mouse joystick sits (the stick gauge), in framebuffer pixels.
  void set_joystick_base(Vec2f centre, float radius);

  input::DriveAction action() const;  // neutral unless ready
  DriveInputState state() const { return state_; }
  std::string status() const;                            // one line for the panel
  bool pause_toggled() const { return pause_toggled_; }  // Esc or the gamepad's Start, this update
  bool stick_held() const { return joystick_.grabbed(); }
  bool faulty() const { return faulty_; }  // the gamepad sent invalid axis values (treated as neutral)

 private:
  void update_gamepad(const FrameInput& input);
  void update_keyboard(const FrameInput& input);
  void update_mouse(const FrameInput& input);
  bool button_pressed(const GamepadSnapshot& pad, SDL_GameControllerButton button) const;

  DeviceChoice& device_;
  input::GamepadConfig config_;
  input::KeyboardDrive keyboard_;
  input::VirtualJoystick joystick_{{100.0, 100.0}, 60.0};
  input::DriveAction gamepad_action_;
  DriveInputState state_ = DriveInputState::ready;
  bool faulty_ = false;
  bool pause_toggled_ = false;
  std::string lost_name_;
  std::set<int> present_when_lost_;               // pads connected when ours vanished
  std::map<int, GamepadSnapshot> previous_pads_;  // last update's pads, for button edges
};

}  // namespace sc
