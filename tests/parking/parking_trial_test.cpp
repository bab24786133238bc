// Trial files: round trip, optional fields, and the exact one-line messages for malformed files.
#include "engine/parking/parking_trial.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/parking/parking_replay.hpp"
#include "engine/parking/parking_sim.hpp"

namespace sc {
namespace {

std::filesystem::path output_dir() {
  const char* dir = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path p = dir ? dir : std::filesystem::temp_directory_path();
  std::filesystem::create_directories(p);
  return p;
}

ParkingTrial sample_trial() {
  ParkingTrial t;
  t.scenario.heading0 = 1.234567890123;
  t.scenario.goal_spot = 17;
  t.scenario.variant = LotVariant::Parked;
  t.scenario.obstacle_seed = 4000000000u;
  t.scenario.reverse_in = true;
  t.actions = {{0.5, -0.25}, {1.0, 0.1 / 3.0}, {-1.0, 1.0}};
  ParkingSim sim(t.scenario);
  t.states.push_back(sim.observation());
  for (const auto& a : t.actions) {
    t.rewards.push_back(sim.step(a).reward);
    t.states.push_back(sim.observation());
  }
  t.success = false;
  t.source = "expert";
  t.created = "2024-05-01T10:00:00Z";
  t.device = "gamepad";
  return t;
}

// Parses `text` as if it were the file "t.json" and returns the error message ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse_parking_trial(parse_json_text(text, "t.json"), "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kScenario = R"("scenario":{"heading0":1.0,"goal":{"spot":3}})";

TEST(ParkingTrial, RoundTripIsExact) {
  const ParkingTrial t = sample_trial();
  const auto file = output_dir() / "parking_trial_round_trip.json";
  write_parking_trial(file, t);
  const ParkingTrial back = read_parking_trial(file);
  EXPECT_EQ(back.scenario, t.scenario);
  EXPECT_EQ(back.actions, t.actions);
  EXPECT_EQ(back.states, t.states);
  EXPECT_EQ(back.rewards, t.rewards);
  EXPECT_EQ(back.success, t.success);
  EXPECT_EQ(back.source, "expert");
  EXPECT_EQ(back.created, t.created);
  EXPECT_EQ(back.device, "gamepad");
  EXPECT_EQ(back.control_hz, 5);
  // Replaying the file reproduces the recorded rewards bit for bit.
  const ParkingReplay replay = replay_parking_trial(back);
  ASSERT_EQ(replay.steps.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(replay.steps[i].reward, t.rewards[i]);
}

TEST(ParkingTrial, MinimalFileWithUnknownFieldsAndGoalByCoordinates) {
  const ParkingTrial t = parse_parking_trial(
      parse_json_text(
          R"({"task":"parking","scenario":{"heading0":0.5,"goal":{"x":-18,"y":14,"heading":-1.5707963},"extra":1},
          "actions":[[0,0]],"comment":"ignored","rewards":null})",
          "t.json"),
      "t.json");
  EXPECT_EQ(t.scenario.goal_spot, 3);
  EXPECT_TRUE(t.scenario.reverse_in);  // heading -pi/2 in a +pi/2 spot
  EXPECT_EQ(t.scenario.variant, LotVariant::Classic);
  EXPECT_EQ(t.actions.size(), 1u);
  EXPECT_TRUE(t.rewards.empty());
  EXPECT_FALSE(t.success.has_value());
}

TEST(ParkingTrial, SubstepRateActionsReplayAsControlSteps) {
  ParkingTrial t;
  t.scenario.heading0 = 0.3;
  t.control_hz = 15;
  t.actions = {{1, 0}, {0.5, 0.2}, {0, -1}, {1, 1}, {1, 1}, {1, 1}};
  const ParkingReplay replay = replay_parking_trial(t);
  ASSERT_EQ(replay.steps.size(), 2u);
  ParkingSim sim(t.scenario);
  sim.step_substeps({ParkingAction{1, 0}, ParkingAction{0.5, 0.2}, ParkingAction{0, -1}});
  sim.step({1, 1});
  EXPECT_EQ(replay.steps[1].vehicle.x, sim.vehicle().x);
  EXPECT_EQ(replay.steps[1].vehicle.heading, sim.vehicle().heading);
  const ParkingTrial back = parse_parking_trial(parking_trial_to_json(t), "mem");
  EXPECT_EQ(back.control_hz, 15);
  EXPECT_EQ(back.control_steps(), 2);
}

TEST(ParkingTrial, MalformedFilesGiveOneExactLine) {
  EXPECT_EQ(error_of(R"({"scenario":{},"actions":[]})"), R"(t.json: $: missing required field "task")");
  EXPECT_EQ(error_of(R"({"task":"writing","actions":[]})"), R"(t.json: $.task: expected "parking", got "writing")");
  EXPECT_EQ(error_of(R"({"task":"parking","actions":[]})"), R"(t.json: $: missing required field "scenario")");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"goal":{"spot":3}},"actions":[]})"),
            R"(t.json: $.scenario: missing required field "heading0")");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"heading0":1,"goal":{"spot":30}},"actions":[]})"),
            "t.json: $.scenario.goal.spot: spot must be in 0..29");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"heading0":1,"goal":{"x":1,"y":14}},"actions":[]})"),
            "t.json: $.scenario.goal: (x, y) is not the centre of a parking spot");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"heading0":1,"goal":{"spot":3,"x":2,"y":14}},"actions":[]})"),
            "t.json: $.scenario.goal: (x, y) is the centre of spot 8, not of spot 3");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"heading0":1,"goal":{"spot":3},"variant":"busy"},"actions":[]})"),
            R"(t.json: $.scenario.variant: unknown lot variant "busy" (expected "classic" or "parked"))");
  EXPECT_EQ(error_of(R"({"task":"parking","scenario":{"heading0":1,"goal":{"spot":3,"heading":0}},"actions":[]})"),
            "t.json: $.scenario.goal.heading: goal heading must point into the spot or out of it (+-pi/2)");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + "}"), R"(t.json: $: missing required field "actions")");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[0.1,0.2],[0.3]]})"),
            "t.json: $.actions[1]: expected an array of 2 numbers [u0, u1]");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[0.1,null]]})"),
            "t.json: $.actions[0][1]: expected a number, got null");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[1e999,0]]})"),
            "t.json: not valid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[1.5,0]]})"),
            "t.json: $.actions[0][0]: value 1.5 is outside [-1, 1]");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[0,0]],"states":[[0,0]]})"),
            "t.json: $.states: expected 2 states (one per control step plus the start), got 1");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[0,0]],"rewards":[-1,"x"]})"),
            "t.json: $.rewards: expected 1 rewards (one per control step), got 2");
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[[0,0]],"success":"yes"})"),
            "t.json: $.success: expected true or false, got string");
}

TEST(ParkingTrial, RejectsAbsurdlyLongActionLists) {
  std::string actions;
  for (int i = 0; i < 10001; ++i) actions += i ? ",[0,0]" : "[0,0]";
  EXPECT_EQ(error_of(R"({"task":"parking",)" + kScenario + R"(,"actions":[)" + actions + "]}"),
            "t.json: $.actions: has 10001 actions, more than the limit of 10000");
}

TEST(ParkingTrial, FileErrorsNameTheFile) {
  const auto file = output_dir() / "parking_trial_broken.json";
  std::ofstream(file) << "{\"task\": \"parking\",";
  try {
    read_parking_trial(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": not valid JSON: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace sc

namespace sc {
namespace {

TEST(ParkingScenarioStart, RoundTripsAndStartsTheSimulationThere) {
  ParkingScenario s;
  s.heading0 = 1.0;
  s.goal_spot = 4;
  s.start = VehicleState{3.5, -2.0, 0.7, -1.25};
  const Json doc = parking_scenario_to_json(s);
  EXPECT_EQ(parse_parking_scenario(JsonView(doc, "start.json")), s);
  ParkingSim sim(s);
  EXPECT_EQ(sim.vehicle(), *s.start);
  ParkingScenario plain = s;
  plain.start.reset();
  EXPECT_FALSE(parking_scenario_to_json(plain).contains("start"));
  EXPECT_EQ(ParkingSim(plain).vehicle(), (VehicleState{0.0, 0.0, 1.0, 0.0}));
}

TEST(ParkingScenarioStart, AbsurdStartSpeedIsRejectedWithItsPath) {
  Json doc = parking_scenario_to_json(ParkingScenario{});
  doc["start"] = {{"x", 0.0}, {"y", 0.0}, {"heading", 0.0}, {"speed", 99.0}};
  try {
    parse_parking_scenario(JsonView(doc, "bad.json"));
    FAIL() << "accepted speed 99";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "bad.json: $.start.speed: value 99 is outside [-40, 40]");
  }
}

}  // namespace
}  // namespace sc
