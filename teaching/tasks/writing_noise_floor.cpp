#include "teaching/tasks/writing_noise_floor.hpp"

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

std::optional<double> recorded_noise_floor(const std::filesystem::path& model) {
  const std::filesystem::path sidecar = model_sidecar_path(model);
  if (!std::filesystem::exists(sidecar)) return std::nullopt;
  const Json doc = read_json_file(sidecar);
  if (!doc.is_object() || !doc.contains(kField)) return std::nullopt;
  const Json& floor = doc[kField];
  if (!floor.is_object() || !floor.contains("value") || !floor["value"].is_number())
    throw InputError(sidecar.string(), std::string("$.") + kField + ".value is not a number");
  return floor["value"].get<double>();
}

void record_noise_floor(const std::filesystem::path& model, const NoiseFloorCalibration& calibration,
                        std::uint64_t seed) {
  const std::filesystem::path sidecar = model_sidecar_path(model);
  if (!std::filesystem::exists(sidecar))
    throw InputError(sidecar.string(), "missing: no sidecar to record the floor in");
  Json doc = read_json_file(sidecar);
  if (!doc.is_object()) throw InputError(sidecar.string(), "not a JSON object");
  doc[kField] = Json{{"value", calibration.floor()},
                     {"percentile", kNoiseFloorPercentile},
                     {"learners", calibration.learners},
                     {"seed", seed},
                     {"segments", calibration.scores.size()}};
  write_json_file(sidecar, doc);
}

}  // namespace sc
