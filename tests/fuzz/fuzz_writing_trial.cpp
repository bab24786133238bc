// Writing trial files (docs/trajectory-format.md): parse, then what the trainer does with a trial it has
// read (infill of the timed trace); whatever parses must write and read back to the same trial.
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/writing_trial.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sc::writing::WritingTrial trial;
  try {
    trial =
        sc::writing::parse_writing_trial(sc::parse_json_text(sc::fuzz::as_text(data, size), "fuzz.json"), "fuzz.json");
  } catch (const sc::InputError&) {
    return 0;
  }
  sc::fuzz::fuzz_require(trial.points.size() <= sc::writing::kMaxTrialPoints, "point cap not applied");
  sc::fuzz::fuzz_require(trial.times.empty() || trial.times.size() == trial.points.size(), "times do not match points");
  const sc::Json written = sc::writing::writing_trial_json(trial);
  const auto back = sc::writing::parse_writing_trial(sc::parse_json_text(written.dump(), "written"), "written");
  sc::fuzz::fuzz_require(back.scenario == trial.scenario && back.points.size() == trial.points.size() &&
                             back.times.size() == trial.times.size() && back.score == trial.score,
                         "trial changed in a write/read round trip");
  try {
    for (const auto& p : sc::writing::infill_trace(trial.trace()).points)
      sc::fuzz::fuzz_require(std::isfinite(p.x) && std::isfinite(p.y), "infilled point is not finite");
  } catch (const sc::InputError&) {}
  return 0;
}
