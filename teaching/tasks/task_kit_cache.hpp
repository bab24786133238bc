#pragma once
// Task kits by what they are built from (task, and for parking the lot), built on first use: a parking kit
// segments its whole expert pool when it is made, so screens that show several sessions (the instructor
// review, the report) keep one kit per kind instead of one per session. A stored session gets the kit it
// ran with: its task and the lot recorded in its settings.
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "teaching/records/record_types.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc {

class TaskKitCache {
 public:
  // make_task_kit(task, shipped model, region); InputError as make_task_kit.
  const TaskKit& kit(const std::string& task, GoalRegion region = GoalRegion::WholeLot);
  // The kit of a stored session; InputError naming the session for unreadable settings.
  const TaskKit& kit_of(const records::SessionRow& session);

 private:
  std::map<std::pair<std::string, GoalRegion>, std::unique_ptr<TaskKit>> kits_;
};

}  // namespace sc
