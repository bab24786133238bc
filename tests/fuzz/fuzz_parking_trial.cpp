// Parking trial files (docs/trajectory-format.md): parse; whatever parses must write and read back to
// the same trial (the trainer re-saves trials it has read, e.g. into the learner database).
#include "engine/core/error.hpp"
#include "engine/parking/parking_trial.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sc::ParkingTrial trial;
  try {
    trial = sc::parse_parking_trial(sc::parse_json_text(sc::fuzz::as_text(data, size), "fuzz.json"), "fuzz.json");
  } catch (const sc::InputError&) {
    return 0;
  }
  sc::fuzz::fuzz_require(trial.actions.size() <= sc::parking::kMaxTrialActions, "action cap not applied");
  const sc::Json written = sc::parking_trial_to_json(trial);
  const sc::ParkingTrial back = sc::parse_parking_trial(sc::parse_json_text(written.dump(), "written"), "written");
  sc::fuzz::fuzz_require(back.scenario == trial.scenario, "scenario changed in a write/read round trip");
  sc::fuzz::fuzz_require(back.actions.size() == trial.actions.size() && back.states.size() == trial.states.size() &&
                             back.rewards.size() == trial.rewards.size() && back.success == trial.success,
                         "trial changed in a write/read round trip");
  return 0;
}
