#include "app/gui/sdl_input.hpp"

#include <algorithm>

namespace sc {
namespace {

int mouse_index(Uint8 sdl_button) {
  switch (sdl_button) {
    case SDL_BUTTON_LEFT:
      return 0;
    case SDL_BUTTON_RIGHT:
      return 1;
    case SDL_BUTTON_MIDDLE:
      return 2;
    default:
      return -1;
  }
}

float axis_value(SDL_GameController* controller, SDL_GameControllerAxis axis) {
  const float raw = static_cast<float>(SDL_GameControllerGetAxis(controller, axis));
  return std::clamp(raw / 32767.0f, -1.0f, 1.0f);
}

}  // namespace

SdlInput::SdlInput() {
  for (int i = 0; i < SDL_NumJoysticks(); ++i) open_controller(i);
}

SdlInput::~SdlInput() {
  for (SDL_GameController* controller : controllers_) SDL_GameControllerClose(controller);
}

void SdlInput::open_controller(int device_index) {
  if (!SDL_IsGameController(device_index)) return;
  const SDL_JoystickID id = SDL_JoystickGetDeviceInstanceID(device_index);
  for (SDL_GameController* c : controllers_)
    if (SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c)) == id) return;  // SDL re-announces at start-up
  if (SDL_GameController* controller = SDL_GameControllerOpen(device_index)) controllers_.push_back(controller);
}

void SdlInput::close_controller(SDL_JoystickID instance_id) {
  auto it = std::find_if(controllers_.begin(), controllers_.end(), [&](SDL_GameController* c) {
    return SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c)) == instance_id;
  });
  if (it == controllers_.end()) return;
  SDL_GameControllerClose(*it);
  controllers_.erase(it);
}

void SdlInput::handle_event(const SDL_Event& event) {
  switch (event.type) {
    case SDL_CONTROLLERDEVICEADDED:
      open_controller(event.cdevice.which);
      break;
    case SDL_CONTROLLERDEVICEREMOVED:
      close_controller(event.cdevice.which);
      break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      if (const int i = mouse_index(event.button.button); i >= 0) {
        if (event.type == SDL_MOUSEBUTTONDOWN)
          edges_.mouse_pressed[static_cast<std::size_t>(i)] = true;
        else
          edges_.mouse_released[static_cast<std::size_t>(i)] = true;
      }
      if (event.button.button == SDL_BUTTON_LEFT)
        edges_.mouse_events.push_back({event.button.timestamp / 1000.0,
                                       {static_cast<float>(event.button.x), static_cast<float>(event.button.y)},
                                       event.type == SDL_MOUSEBUTTONDOWN});
      break;
    case SDL_MOUSEMOTION:  // window points here; poll() converts them to framebuffer pixels
      edges_.mouse_events.push_back({event.motion.timestamp / 1000.0,
                                     {static_cast<float>(event.motion.x), static_cast<float>(event.motion.y)},
                                     (event.motion.state & SDL_BUTTON_LMASK) != 0});
      break;
    case SDL_MOUSEWHEEL:
      edges_.wheel += static_cast<float>(event.wheel.y);
      break;
    case SDL_KEYDOWN:
      if (event.key.repeat == 0 && event.key.keysym.scancode < SDL_NUM_SCANCODES)
        edges_.keys_pressed[static_cast<std::size_t>(event.key.keysym.scancode)] = true;
      break;
    default:
      break;
  }
}

FrameInput SdlInput::poll(SDL_Window* window, float pixel_density) {
  FrameInput input = edges_;
  edges_ = FrameInput{};
  int mx = 0, my = 0;
  const Uint32 buttons = SDL_GetMouseState(&mx, &my);
  input.mouse_inside = SDL_GetMouseFocus() == window;
  input.time_seconds = static_cast<double>(SDL_GetTicks64()) / 1000.0;
  for (MouseEvent& e : input.mouse_events) e.pixels = e.pixels * pixel_density;
  input.mouse_pixels = {static_cast<float>(mx) * pixel_density, static_cast<float>(my) * pixel_density};
  input.mouse_down = {(buttons & SDL_BUTTON_LMASK) != 0, (buttons & SDL_BUTTON_RMASK) != 0,
                      (buttons & SDL_BUTTON_MMASK) != 0};
  int key_count = 0;
  const Uint8* keys = SDL_GetKeyboardState(&key_count);
  for (int i = 0; i < std::min(key_count, static_cast<int>(SDL_NUM_SCANCODES)); ++i)
    input.keys_down[static_cast<std::size_t>(i)] = keys[i] != 0;
  for (SDL_GameController* controller : controllers_) {
    GamepadSnapshot pad;
    pad.instance_id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(controller));
    const char* name = SDL_GameControllerName(controller);
    pad.name = name != nullptr ? name : "Gamepad";
    for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX; ++a)
      pad.axes[static_cast<std::size_t>(a)] = axis_value(controller, static_cast<SDL_GameControllerAxis>(a));
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
      pad.buttons[static_cast<std::size_t>(b)] =
          SDL_GameControllerGetButton(controller, static_cast<SDL_GameControllerButton>(b)) != 0;
    input.gamepads.push_back(std::move(pad));
  }
  return input;
}

}  // namespace sc
