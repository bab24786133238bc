#include "teaching/tasks/task_kit_factory.hpp"

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_noise_floor.hpp"

namespace sc {

ChosenExtractor choose_skill_extractor(TaskKind kind, const std::filesystem::path& model) {
  const std::string task(to_string(kind));
  const bool parking = kind == TaskKind::parking;
  const int state_dim = parking ? kParkingStateDim : writing::kWritingStateDim;
  const int action_dim = parking ? kParkingActionDim : 2;
  auto load = [&](const std::filesystem::path& file) {
    return std::make_shared<CompileExtractor>(CompileExtractor::load(file, task, state_dim, action_dim));
  };
  if (!model.empty()) return {load(model), "", model};
  const int slices = parking ? kParkingTimeSlices : kWritingTimeSlices;
  const std::string relative = "assets/models/" + task + ".pt";
  const std::filesystem::path shipped = asset_dir() / "models" / (task + ".pt");
  // The missing case names the asset relative to the asset folder, so the notice (shown on screen and in
  // goldens) does not depend on where the checkout lives.
  if (!std::filesystem::exists(shipped))
    return {std::make_shared<TimeHeuristicExtractor>(slices), relative + ": missing; using the time heuristic", {}};
  try {
    return {load(shipped), "", shipped};
  } catch (const InputError& e) {
    return {std::make_shared<TimeHeuristicExtractor>(slices), std::string(e.what()) + "; using the time heuristic", {}};
  }
}

std::unique_ptr<TaskKit> make_parking_kit(const std::filesystem::path& model, GoalRegion region,
                                          std::optional<NoiseFloor> execution_noise_floor,
                                          ParkingDriveReading reading) {
  ChosenExtractor chosen = choose_skill_extractor(TaskKind::parking, model);
  return std::make_unique<ParkingKit>(
      chosen.extractor, chosen.notice,
      ParkingKitOptions{default_parking_pool_file(region), ParkingPoolOptions{100, 0, region}, execution_noise_floor,
                        reading});
}

std::unique_ptr<TaskKit> make_task_kit(TaskKind task, const std::filesystem::path& model, GoalRegion region) {
  if (task == TaskKind::parking) return make_parking_kit(model, region, std::nullopt);
  ChosenExtractor chosen = choose_skill_extractor(task, model);
  try {
    return make_writing_kit(chosen.extractor, chosen.model, chosen.notice);
  } catch (const InputError& e) {
    if (!model.empty()) throw;  // the user's own model: say so and stop, as for its model file
    return make_writing_kit(chosen.extractor, {},
                            std::string(e.what()) + "; quality-aware expertise without a noise floor");
  }
}

std::unique_ptr<WritingKit> make_writing_kit(std::shared_ptr<const SkillExtractor> extractor,
                                             const std::filesystem::path& model, std::string notice) {
  WritingKitOptions options;
  if (!model.empty()) options.execution_noise_floor = recorded_noise_floor(model);
  return std::make_unique<WritingKit>(std::move(extractor), std::move(notice), options);
}

std::unique_ptr<TaskKit> make_task_kit(const std::string& task, const std::filesystem::path& model, GoalRegion region) {
  return make_task_kit(parse_task_kind(task, "task"), model, region);
}

}  // namespace sc
