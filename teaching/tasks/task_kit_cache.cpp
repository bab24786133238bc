#include "teaching/tasks/task_kit_cache.hpp"

#include "teaching/sessions/session_settings.hpp"

namespace sc {

const TaskKit& TaskKitCache::kit(const std::string& task, GoalRegion region) {
  // Writing has no lots: one kit, whatever region is asked for.
  if (parse_task_kind(task, "task") == TaskKind::writing) region = GoalRegion::WholeLot;
  std::unique_ptr<TaskKit>& slot = kits_[{task, region}];
  if (!slot) slot = make_task_kit(task, {}, region);
  return *slot;
}

const TaskKit& TaskKitCache::kit_of(const records::SessionRow& session) {
  return kit(session.task, settings_of_session(session).lot());
}

}  // namespace sc
