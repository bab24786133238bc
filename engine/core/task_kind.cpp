#include "engine/core/task_kind.hpp"

#include <string>

#include "engine/core/error.hpp"

namespace sc {

std::string_view to_string(TaskKind task) { return task == TaskKind::parking ? "parking" : "writing"; }

std::optional<TaskKind> task_kind_of(std::string_view text) {
  if (text == "parking") return TaskKind::parking;
  if (text == "writing") return TaskKind::writing;
  return std::nullopt;
}

TaskKind parse_task_kind(std::string_view text, std::string_view where) {
  if (const auto kind = task_kind_of(text)) return *kind;
  throw InputError(where, "'" + one_line(text) + "' is not parking or writing");
}

}  // namespace sc
