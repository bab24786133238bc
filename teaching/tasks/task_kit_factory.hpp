#pragma once
// The task kit the trainer, `skillcoach learn` and `skillcoach diagnose` use: the task's trained CompILE model
// (assets/models/<task>.pt) when it loads, otherwise the time heuristic (the paper's baseline) with a notice
// saying why, so a checkout without trained models still trains and diagnoses.
#include <filesystem>
#include <memory>
#include <string>

#include "teaching/sessions/task_kit.hpp"

namespace sc {

struct ChosenExtractor {
  std::shared_ptr<const SkillExtractor> extractor;
  std::string notice;  // why the time heuristic is used; empty for the trained model
};

// The extractor make_task_kit gives the task's kit (same rules), for tools that build a kit of their own
// (e.g. the synthetic students' study-corner pool).
ChosenExtractor choose_skill_extractor(const std::string& task, const std::filesystem::path& model = {});

// task: "parking" or "writing" (InputError otherwise, or when the task's data is missing). A non-empty
// `model` must load (the user asked for it: its InputError propagates); an empty one means the shipped model.
std::unique_ptr<TaskKit> make_task_kit(const std::string& task, const std::filesystem::path& model = {});

}  // namespace sc
