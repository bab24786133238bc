#include "engine/input/sdl_input_mapping.hpp"

#include <algorithm>

namespace sc::input {

double normalized_stick_axis(Sint16 value) {
  return value < 0 ? static_cast<double>(value) / 32768.0 : static_cast<double>(value) / 32767.0;
}

double normalized_trigger_axis(Sint16 value) { return static_cast<double>(std::max<Sint16>(value, 0)) / 32767.0; }

GamepadSample read_gamepad(SDL_GameController* controller) {
  return {
      normalized_stick_axis(SDL_GameControllerGetAxis(controller, SDL_CONTROLLER_AXIS_LEFTX)),
      normalized_stick_axis(SDL_GameControllerGetAxis(controller, SDL_CONTROLLER_AXIS_LEFTY)),
      normalized_trigger_axis(SDL_GameControllerGetAxis(controller, SDL_CONTROLLER_AXIS_TRIGGERLEFT)),
      normalized_trigger_axis(SDL_GameControllerGetAxis(controller, SDL_CONTROLLER_AXIS_TRIGGERRIGHT)),
  };
}

std::optional<DriveKey> drive_key_for_scancode(SDL_Scancode scancode) {
  switch (scancode) {
    case SDL_SCANCODE_UP:
      return DriveKey::Up;
    case SDL_SCANCODE_DOWN:
      return DriveKey::Down;
    case SDL_SCANCODE_LEFT:
      return DriveKey::Left;
    case SDL_SCANCODE_RIGHT:
      return DriveKey::Right;
    case SDL_SCANCODE_W:
      return DriveKey::W;
    case SDL_SCANCODE_A:
      return DriveKey::A;
    case SDL_SCANCODE_S:
      return DriveKey::S;
    case SDL_SCANCODE_D:
      return DriveKey::D;
    case SDL_SCANCODE_LSHIFT:
      return DriveKey::LeftShift;
    case SDL_SCANCODE_RSHIFT:
      return DriveKey::RightShift;
    default:
      return std::nullopt;
  }
}

}  // namespace sc::input
