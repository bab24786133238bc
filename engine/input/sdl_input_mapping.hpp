#pragma once
// Thin conversions from SDL's raw values to the SDL-independent input types.
#include <optional>

#include <SDL.h>

#include "engine/input/gamepad_mapping.hpp"
#include "engine/input/keyboard_drive.hpp"

namespace sc::input {

// SDL stick axes are Sint16 in [-32768, 32767]; dividing both halves by their own extent maps the full
// range onto exactly [-1, 1] (dividing by 32767 alone would report -32768 as out of range).
double normalized_stick_axis(Sint16 value);
// SDL controller triggers are 0..32767 (negative values would be a driver bug and are treated as 0).
double normalized_trigger_axis(Sint16 value);

// Reads the four axes the driving mapping uses from an open controller.
GamepadSample read_gamepad(SDL_GameController* controller);

// Physical key positions (scancodes), so WASD stays where it is on AZERTY/QWERTZ layouts.
std::optional<DriveKey> drive_key_for_scancode(SDL_Scancode scancode);

}  // namespace sc::input
