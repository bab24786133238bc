#pragma once
// The two tasks SkillCoach teaches, as a type. Text ("parking", "writing": a trial file's "task", `--task`,
// the database's task column) is parsed once where it enters; code then compares kinds, never strings.
#include <optional>
#include <string_view>

namespace sc {

enum class TaskKind { parking, writing };

std::string_view to_string(TaskKind task);  // "parking", "writing"
// nullopt for any other text.
std::optional<TaskKind> task_kind_of(std::string_view text);
// InputError at `where` ("'x' is not parking or writing") for any other text.
TaskKind parse_task_kind(std::string_view text, std::string_view where);

}  // namespace sc
