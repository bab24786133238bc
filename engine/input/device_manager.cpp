#include "engine/input/device_manager.hpp"

#include <algorithm>

#include "engine/input/sdl_input_mapping.hpp"

namespace sc::input {

void DeviceManager::ControllerCloser::operator()(SDL_GameController* controller) const {
  SDL_GameControllerClose(controller);
}

DeviceManager::DeviceManager(InputSource source, GamepadConfig config) : source_(source), config_(config) {
  validate(config_);
  // SDL also queues an ADDED event for each of these; open_gamepad() ignores duplicates.
  if (SDL_WasInit(SDL_INIT_GAMECONTROLLER) == 0) return;
  for (int i = 0; i < SDL_NumJoysticks(); ++i)
    if (SDL_IsGameController(i)) open_gamepad(i);
}

DeviceManager::~DeviceManager() = default;

bool DeviceManager::handle_event(const SDL_Event& event) {
  switch (event.type) {
    case SDL_CONTROLLERDEVICEADDED:
      open_gamepad(event.cdevice.which);
      return true;
    case SDL_CONTROLLERDEVICEREMOVED:
      remove_gamepad(event.cdevice.which);
      return true;
    case SDL_CONTROLLERBUTTONDOWN:
      pick_up_gamepad(event.cbutton.which);
      return true;
    case SDL_CONTROLLERAXISMOTION:
    case SDL_CONTROLLERBUTTONUP:
      return true;
    case SDL_JOYDEVICEADDED:
      if (!SDL_IsGameController(event.jdevice.which)) {
        const char* name = SDL_JoystickNameForIndex(event.jdevice.which);
        notice_ = std::string("joystick '") + (name ? name : "unnamed") +
                  "' has no gamepad mapping and cannot be used for driving";
      }
      return false;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
      return handle_key(event.key);
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
    case SDL_MOUSEMOTION:
      return handle_mouse(event);
    case SDL_WINDOWEVENT:
      // Key-up and button-up events will not reach us while unfocused: forget held keys and the knob.
      if (event.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
        keyboard_.release_all();
        joystick_.release();
      }
      return false;
    default:
      return false;
  }
}

void DeviceManager::open_gamepad(int device_index) {
  const SDL_JoystickID id = SDL_JoystickGetDeviceInstanceID(device_index);
  if (id < 0 || find(id) != nullptr) return;
  SDL_GameController* controller = SDL_GameControllerOpen(device_index);
  if (controller == nullptr) {
    notice_ = std::string("could not open gamepad: ") + SDL_GetError();
    return;
  }
  const char* name = SDL_GameControllerName(controller);
  gamepads_.push_back({{id, name ? name : "unnamed gamepad"}, {controller, ControllerCloser{}}});
  if (!active_) {
    active_ = id;
    lost_ = false;  // a device is back: resume
  }
}

void DeviceManager::remove_gamepad(SDL_JoystickID instance_id) {
  const auto it = std::find_if(gamepads_.begin(), gamepads_.end(),
                               [&](const OpenGamepad& g) { return g.info.instance_id == instance_id; });
  if (it == gamepads_.end()) return;
  const std::string name = it->info.name;
  gamepads_.erase(it);
  if (active_ != instance_id) return;
  active_.reset();
  if (source_ == InputSource::Gamepad) {
    lost_ = true;
    lost_name_ = name;
  } else if (!gamepads_.empty()) {
    active_ = gamepads_.front().info.instance_id;  // not in use: no reason to pause
  }
}

void DeviceManager::pick_up_gamepad(SDL_JoystickID instance_id) {
  if (find(instance_id) == nullptr) return;
  active_ = instance_id;
  lost_ = false;
}

bool DeviceManager::handle_key(const SDL_KeyboardEvent& key) {
  const std::optional<DriveKey> drive_key = drive_key_for_scancode(key.keysym.scancode);
  if (!drive_key) return false;
  if (key.repeat == 0) keyboard_.set_pressed(*drive_key, key.type == SDL_KEYDOWN);
  return true;
}

bool DeviceManager::handle_mouse(const SDL_Event& event) {
  if (event.type == SDL_MOUSEMOTION) {
    if (!joystick_.grabbed()) return false;
    joystick_.drag({static_cast<double>(event.motion.x), static_cast<double>(event.motion.y)});
    return true;
  }
  if (event.button.button != SDL_BUTTON_LEFT) return false;
  if (event.type == SDL_MOUSEBUTTONDOWN)
    return joystick_.press({static_cast<double>(event.button.x), static_cast<double>(event.button.y)});
  if (!joystick_.grabbed()) return false;
  joystick_.release();
  return true;
}

void DeviceManager::set_source(InputSource source) {
  source_ = source;
  lost_ = false;
  if (!active_ && !gamepads_.empty()) active_ = gamepads_.front().info.instance_id;
}

InputState DeviceManager::state() const {
  if (source_ != InputSource::Gamepad) return InputState::Ready;
  if (lost_) return InputState::DeviceLost;
  return active_ ? InputState::Ready : InputState::WaitingForGamepad;
}

std::string DeviceManager::status_message() const {
  switch (state()) {
    case InputState::DeviceLost:
      return "Gamepad '" + lost_name_ +
             "' was disconnected: the trial is paused. Reconnect it, press a button on another gamepad, "
             "or choose the mouse or keyboard to continue.";
    case InputState::WaitingForGamepad:
      return "No gamepad connected: plug one in, or choose the mouse or keyboard.";
    case InputState::Ready:
      break;
  }
  switch (source_) {
    case InputSource::Gamepad:
      return "Gamepad: " + find(*active_)->info.name;
    case InputSource::VirtualJoystick:
      return "Mouse: drag the on-screen stick";
    case InputSource::Keyboard:
      return "Keyboard: arrows or WASD";
  }
  return {};
}

std::vector<GamepadInfo> DeviceManager::gamepads() const {
  std::vector<GamepadInfo> out;
  out.reserve(gamepads_.size());
  for (const OpenGamepad& g : gamepads_) out.push_back(g.info);
  return out;
}

std::optional<GamepadInfo> DeviceManager::active_gamepad() const {
  if (!active_) return std::nullopt;
  return find(*active_)->info;
}

InputReading DeviceManager::read() const {
  if (state() != InputState::Ready) return {};
  switch (source_) {
    case InputSource::Keyboard:
      return {keyboard_.action(), false};
    case InputSource::VirtualJoystick:
      return {joystick_.action(), false};
    case InputSource::Gamepad:
      break;
  }
  return map_gamepad(read_gamepad(find(*active_)->controller.get()), config_);
}

void DeviceManager::set_gamepad_config(const GamepadConfig& config) {
  validate(config);
  config_ = config;
}

const DeviceManager::OpenGamepad* DeviceManager::find(SDL_JoystickID instance_id) const {
  for (const OpenGamepad& g : gamepads_)
    if (g.info.instance_id == instance_id) return &g;
  return nullptr;
}

}  // namespace sc::input
