#include "engine/input/gamepad_config_json.hpp"

namespace sc::input {
namespace {

// Same bounds as validate(), checked here so the error carries the JSON path.
constexpr double kMaxDeadZone = 0.9;

ThrottleControl throttle_from(const JsonView& node) {
  const std::string name = node.string();
  if (name == "stick") return ThrottleControl::LeftStick;
  if (name == "triggers") return ThrottleControl::Triggers;
  node.fail("expected \"stick\" or \"triggers\", got \"" + name + "\"");
}

}  // namespace

GamepadConfig gamepad_config_from_json(const JsonView& node) {
  if (!node.is_object()) node.fail("expected an object with the gamepad settings");
  GamepadConfig config;
  if (auto v = node.find("throttle")) config.throttle = throttle_from(*v);
  if (auto v = node.find("stick_dead_zone")) config.stick_dead_zone = v->number_in(0.0, kMaxDeadZone);
  if (auto v = node.find("trigger_dead_zone")) config.trigger_dead_zone = v->number_in(0.0, kMaxDeadZone);
  validate(config);
  return config;
}

Json to_json(const GamepadConfig& config) {
  return {{"throttle", config.throttle == ThrottleControl::Triggers ? "triggers" : "stick"},
          {"stick_dead_zone", config.stick_dead_zone},
          {"trigger_dead_zone", config.trigger_dead_zone}};
}

}  // namespace sc::input
