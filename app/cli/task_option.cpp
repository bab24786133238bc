#include "app/cli/task_option.hpp"

namespace sc::cli {

CLI::Option* add_task_option(CLI::App& sub, TaskKind& task, const std::string& help) {
  return sub
      .add_option_function<std::string>(
          "--task", [&task](const std::string& text) { task = parse_task_kind(text, "--task"); }, help)
      ->check(CLI::IsMember({std::string(to_string(TaskKind::parking)), std::string(to_string(TaskKind::writing))}));
}

}  // namespace sc::cli
