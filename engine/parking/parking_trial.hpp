#pragma once
// Parking trial files: one JSON document per trial (format: docs/trajectory-format.md, "Parking trials").
//   {"task":"parking","scenario":{...},"actions":[[u0,u1],...], optional "states","rewards","success",...}
// Unknown fields are ignored; any problem throws InputError naming the file, the JSON path and the problem.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/parking/parking_scenario.hpp"
#include "engine/parking/parking_sim.hpp"

namespace sc {

namespace parking {
// More actions than this cannot come from one episode (100 control steps, at most 3 inputs each) plus
// generous slack; the cap keeps a corrupt or hostile file from exhausting memory.
inline constexpr std::size_t kMaxTrialActions = 10000;
}  // namespace parking

struct ParkingTrial {
  ParkingScenario scenario;
  // 5: one action per 0.2 s control step (the reference). 15: one action per 1/15 s sub-step, as recorded
  // by the "responsive" input mode; the action count is then a multiple of 3.
  int control_hz = parking::kControlHz;
  std::vector<ParkingAction> actions;
  // Optional records of the run (T+1 observations including the start, T rewards for T control steps).
  std::vector<ParkingObservation> states;
  std::vector<double> rewards;
  std::optional<bool> success;
  std::string source;   // "expert", "learner", ... ("" = not recorded)
  std::string created;  // ISO 8601 time, free text
  std::string device;   // "gamepad", "mouse", "keyboard", ... free text

  int control_steps() const;  // number of control steps the actions cover
};

// The "scenario" object. Accepts the goal as {"spot":k} and/or {"x","y","heading"}; when both are given
// they must agree. A bare scenario object is what `skillcoach expert --scenario` also accepts.
ParkingScenario parse_parking_scenario(const JsonView& scenario);
Json parking_scenario_to_json(const ParkingScenario& scenario);

ParkingTrial parse_parking_trial(const Json& doc, std::string_view source);
ParkingTrial read_parking_trial(const std::filesystem::path& file);
Json parking_trial_to_json(const ParkingTrial& trial);
void write_parking_trial(const std::filesystem::path& file, const ParkingTrial& trial);

}  // namespace sc
