#pragma once
// The task kits the trainer uses: the trained CompILE model from assets/models/<task>.pt when it loads,
// otherwise the time heuristic with a notice the welcome screen shows (a fresh checkout still trains).
#include <memory>
#include <string>

#include "teaching/sessions/task_kit.hpp"

namespace sc {

// task: "parking" or "writing"; InputError otherwise, or when the task's data is missing.
std::unique_ptr<TaskKit> make_trainer_kit(const std::string& task);

}  // namespace sc
