#pragma once
// The gamepad section of a settings file, e.g.
//   "gamepad": {"throttle": "triggers", "stick_dead_zone": 0.15, "trigger_dead_zone": 0.05}
// Every member is optional (missing = default); unknown members are ignored like everywhere else.
#include "engine/core/json_file.hpp"
#include "engine/input/gamepad_mapping.hpp"

namespace sc::input {

// Throws InputError naming the file and JSON path (e.g. "settings.json: $.gamepad.stick_dead_zone: ...").
GamepadConfig gamepad_config_from_json(const JsonView& node);
Json to_json(const GamepadConfig& config);

}  // namespace sc::input
