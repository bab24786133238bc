#pragma once
// The task kit the trainer, `skillcoach learn` and `skillcoach diagnose` use: the task's trained CompILE model
// (assets/models/<task>.pt) when it loads, otherwise the time heuristic (the paper's baseline) with a notice
// saying why, so a checkout without trained models still trains and diagnoses.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/task_kind.hpp"
#include "engine/parking/parking_scenario.hpp"
#include "teaching/sessions/task_kit.hpp"
#include "teaching/tasks/parking_drive_reading.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc {

// The skill extractor for `kind`: the model file `model` when given (its InputError propagates: the user asked for
// it), else the shipped assets/models/<task>.pt, else the time heuristic with a notice saying why. Models are checked
// for their task and the task's state and action dimensions.
struct ChosenExtractor {
  std::shared_ptr<const SkillExtractor> extractor;
  std::string notice;           // why the time heuristic is used; empty for the trained model
  std::filesystem::path model;  // the model file loaded; empty for the time heuristic
};
ChosenExtractor choose_skill_extractor(TaskKind kind, const std::filesystem::path& model);

// InputError when the task's data is missing. A non-empty
// `model` must load (the user asked for it: its InputError propagates); an empty one means the shipped model.
// Parking draws its pool and fresh scenarios in `region` (the shipped pool of that region); writing has no
// regions and ignores it.
std::unique_ptr<TaskKit> make_task_kit(TaskKind task, const std::filesystem::path& model = {},
                                       GoalRegion region = GoalRegion::WholeLot);
// The parking kit make_task_kit builds, with quality-aware expertise's noise floor set (research:
// `evaluate-diagnosis --apply-noise-floor`; the shipped kit uses none, ParkingKitOptions).
std::unique_ptr<TaskKit> make_parking_kit(const std::filesystem::path& model, GoalRegion region,
                                          std::optional<NoiseFloor> execution_noise_floor,
                                          ParkingDriveReading reading = {});
// A writing kit (default options) for `extractor`, with the noise floor recorded with `model`
// (writing_noise_floor.hpp; none when `model` is empty or records none): what make_task_kit builds for writing,
// for callers that choose the extractor themselves (evaluate-skills, tests).
std::unique_ptr<WritingKit> make_writing_kit(std::shared_ptr<const SkillExtractor> extractor,
                                             const std::filesystem::path& model, std::string notice = "");
// The same for a task named in text (a stored session's task column): InputError for anything else.
std::unique_ptr<TaskKit> make_task_kit(const std::string& task, const std::filesystem::path& model = {},
                                       GoalRegion region = GoalRegion::WholeLot);

}  // namespace sc
