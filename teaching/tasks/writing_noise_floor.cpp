#include "teaching/tasks/writing_noise_floor.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/tasks/writing_planted_weakness.hpp"

namespace sc {
namespace {

constexpr const char* kField = "execution_noise_floor";

}  // namespace

NoiseFloorCalibration calibrate_writing_noise_floor(const WritingKit& kit, int learners, std::uint64_t seed) {
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  const std::vector<std::string> words = pretest_words(kit);
  std::vector<std::vector<Json>> trials;
  for (int i = 0; i < learners; ++i)
    trials.push_back(planted_pretest_trials(glyphs, words, noise_only_learner(seed, i)));
  return calibrate_noise_floor(kit, trials);
}

std::optional<NoiseFloor> recorded_noise_floor(const std::filesystem::path& model) {
  const std::filesystem::path sidecar = model_sidecar_path(model);
  if (!std::filesystem::exists(sidecar)) return std::nullopt;
  const Json doc = read_json_file(sidecar);
  if (!doc.is_object() || !doc.contains(kField)) return std::nullopt;
  const Json& floor = doc[kField];
  const auto number = [&](const char* key) {
    if (!floor.is_object() || !floor.contains(key) || !floor[key].is_number())
      throw InputError(sidecar.string(), std::string("$.") + kField + "." + key + " is not a number");
    const double value = floor[key].get<double>();
    if (!(std::isfinite(value) && value <= 0.0))
      throw InputError(sidecar.string(), std::string("$.") + kField + "." + key + " must be <= 0 (scores are)");
    return value;
  };
  NoiseFloor out(number("value"));
  if (floor.contains("repeated_twice")) out.repeated_twice = number("repeated_twice");
  if (floor.contains("repeated_more")) out.repeated_more = number("repeated_more");
  return out;
}

void record_noise_floor(const std::filesystem::path& model, const NoiseFloorCalibration& calibration,
                        std::uint64_t seed) {
  const std::filesystem::path sidecar = model_sidecar_path(model);
  if (!std::filesystem::exists(sidecar))
    throw InputError(sidecar.string(), "missing: no sidecar to record the floor in");
  Json doc = read_json_file(sidecar);
  if (!doc.is_object()) throw InputError(sidecar.string(), "not a JSON object");
  const NoiseFloor floor = calibration.noise_floor();
  Json record{{"value", floor.segment},
              {"percentile", kNoiseFloorPercentile},
              {"learners", calibration.learners},
              {"seed", seed},
              {"segments", calibration.scores.size()},
              {"skills_twice", calibration.skill_twice.size()},
              {"skills_more", calibration.skill_more.size()}};
  if (floor.repeated_twice) record["repeated_twice"] = *floor.repeated_twice;
  if (floor.repeated_more) record["repeated_more"] = *floor.repeated_more;
  doc[kField] = std::move(record);
  write_json_file(sidecar, doc);
}

}  // namespace sc
