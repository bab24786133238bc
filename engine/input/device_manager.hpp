#pragma once
// All of the learner's driving devices behind one object fed with SDL events: gamepads (SDL GameController,
// hot-plugged), the on-screen virtual joystick (mouse) and the keyboard. The app forwards every SDL event to
// handle_event(), asks state() each frame (anything but Ready means: pause the trial and show
// status_message()), and reads action() for the ActionLatch.
//
// Hot-plug rules:
//  - A gamepad connected at any time is opened and listed; if none was in use it becomes the active one.
//  - When the gamepad in use is disconnected while the source is Gamepad, state() becomes DeviceLost (the
//    trial pauses; nothing recorded is touched, recordings live in the ActionLatch). It becomes Ready
//    again when a gamepad is connected (the same or another), when a button is pressed on another gamepad
//    that is still connected (the learner picked it up), or when the app switches the source.
//  - Pressing a button on a connected, inactive gamepad makes it the active one.
// Requires SDL_Init(SDL_INIT_GAMECONTROLLER) before construction and destruction before SDL_Quit().
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <SDL.h>

#include "engine/input/gamepad_mapping.hpp"
#include "engine/input/keyboard_drive.hpp"
#include "engine/input/virtual_joystick.hpp"

namespace sc::input {

enum class InputSource { Gamepad, VirtualJoystick, Keyboard };
enum class InputState {
  Ready,              // the selected source can drive
  WaitingForGamepad,  // source is Gamepad but none is connected (yet)
  DeviceLost,         // the gamepad in use was disconnected: pause the trial
};

struct GamepadInfo {
  SDL_JoystickID instance_id = -1;
  std::string name;
};

class DeviceManager {
 public:
  explicit DeviceManager(InputSource source = InputSource::Gamepad, GamepadConfig config = {});
  ~DeviceManager();
  DeviceManager(const DeviceManager&) = delete;
  DeviceManager& operator=(const DeviceManager&) = delete;

  // Consumes device, keyboard, mouse and focus events; returns true when the event was input for driving
  // (a mouse press that grabbed the virtual joystick, a drive key, a controller event).
  bool handle_event(const SDL_Event& event);

  void set_source(InputSource source);
  InputSource source() const { return source_; }
  InputState state() const;
  // One line for the UI: the device in use, or why the trial is paused and how to continue.
  std::string status_message() const;
  // Last problem with a device that is not a pause (e.g. a joystick with no gamepad mapping); empty if none.
  const std::string& notice() const { return notice_; }

  std::vector<GamepadInfo> gamepads() const;
  std::optional<GamepadInfo> active_gamepad() const;

  // The live action of the selected source; neutral (0, 0) unless state() == Ready. `faulty` is set when the
  // gamepad reported invalid axis values (they were replaced by neutral).
  InputReading read() const;
  DriveAction action() const { return read().action; }

  void set_gamepad_config(const GamepadConfig& config);  // throws InputError on invalid dead zones
  const GamepadConfig& gamepad_config() const { return config_; }
  VirtualJoystick& virtual_joystick() { return joystick_; }
  const VirtualJoystick& virtual_joystick() const { return joystick_; }
  KeyboardDrive& keyboard() { return keyboard_; }
  const KeyboardDrive& keyboard() const { return keyboard_; }

 private:
  struct ControllerCloser {
    void operator()(SDL_GameController* controller) const;
  };
  struct OpenGamepad {
    GamepadInfo info;
    std::unique_ptr<SDL_GameController, ControllerCloser> controller;
  };

  void open_gamepad(int device_index);
  void remove_gamepad(SDL_JoystickID instance_id);
  void pick_up_gamepad(SDL_JoystickID instance_id);
  bool handle_key(const SDL_KeyboardEvent& key);
  bool handle_mouse(const SDL_Event& event);
  const OpenGamepad* find(SDL_JoystickID instance_id) const;

  InputSource source_;
  GamepadConfig config_;
  std::vector<OpenGamepad> gamepads_;  // in connection order
  std::optional<SDL_JoystickID> active_;
  bool lost_ = false;
  std::string lost_name_;
  std::string notice_;
  KeyboardDrive keyboard_;
  VirtualJoystick joystick_{{100.0, 100.0}, 60.0};  // the renderer places it with set_base()
};

}  // namespace sc::input
