#include "engine/input/gamepad_config_json.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc::input {
namespace {

std::string error_for(const char* text) {
  const Json doc = Json::parse(text);
  try {
    gamepad_config_from_json(JsonView(doc, "settings.json").at("gamepad"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(GamepadConfigJson, MissingMembersKeepDefaultsAndUnknownOnesAreIgnored) {
  const Json doc = Json::parse(R"({"throttle": "triggers", "rumble": true})");
  const GamepadConfig c = gamepad_config_from_json(JsonView(doc, "settings.json"));
  EXPECT_EQ(c.throttle, ThrottleControl::Triggers);
  EXPECT_EQ(c.stick_dead_zone, GamepadConfig{}.stick_dead_zone);
  EXPECT_EQ(c.trigger_dead_zone, GamepadConfig{}.trigger_dead_zone);
}

TEST(GamepadConfigJson, RoundTrips) {
  GamepadConfig c;
  c.throttle = ThrottleControl::Triggers;
  c.stick_dead_zone = 0.2;
  c.trigger_dead_zone = 0.0;
  const Json doc = Json::parse(to_json(c).dump());
  const GamepadConfig back = gamepad_config_from_json(JsonView(doc, "settings.json"));
  EXPECT_EQ(back.throttle, c.throttle);
  EXPECT_EQ(back.stick_dead_zone, c.stick_dead_zone);
  EXPECT_EQ(back.trigger_dead_zone, c.trigger_dead_zone);
}

TEST(GamepadConfigJson, ErrorsNameTheFileAndPath) {
  EXPECT_EQ(error_for(R"({"gamepad": {"stick_dead_zone": 1.5}})"),
            "settings.json: $.gamepad.stick_dead_zone: value 1.5 is outside [0, 0.9]");
  EXPECT_EQ(error_for(R"({"gamepad": {"throttle": "pedals"}})"),
            "settings.json: $.gamepad.throttle: expected \"stick\" or \"triggers\", got \"pedals\"");
  EXPECT_EQ(error_for(R"({"gamepad": {"trigger_dead_zone": "big"}})"),
            "settings.json: $.gamepad.trigger_dead_zone: expected a number, got string");
  EXPECT_EQ(error_for(R"({"gamepad": [0.1]})"),
            "settings.json: $.gamepad: expected an object with the gamepad settings");
}

}  // namespace
}  // namespace sc::input
