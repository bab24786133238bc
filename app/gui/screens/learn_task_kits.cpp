#include "app/gui/screens/learn_task_kits.hpp"

#include <filesystem>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc {

std::unique_ptr<TaskKit> make_trainer_kit(const std::string& task) {
  if (task != "parking" && task != "writing") throw InputError("task", "'" + task + "' is not parking or writing");
  const int k = task == "parking" ? kParkingTimeSlices : kWritingTimeSlices;
  std::shared_ptr<const SkillExtractor> extractor;
  std::string notice;
  const std::filesystem::path model = asset_dir() / "models" / (task + ".pt");
  try {
    if (!std::filesystem::exists(model)) throw InputError(model.string(), "missing");
    extractor = std::make_shared<CompileExtractor>(CompileExtractor::load(model, task));
  } catch (const InputError& e) {
    extractor = std::make_shared<TimeHeuristicExtractor>(k);
    notice = std::string(e.what()) + "; using the time heuristic";
  }
  if (task == "parking")
    return std::make_unique<ParkingKit>(extractor, notice, ParkingKitOptions{default_parking_pool_file(), {}});
  return std::make_unique<WritingKit>(extractor, notice, WritingKitOptions{});
}

}  // namespace sc
