#include "app/cli/command_registry.hpp"

#include <algorithm>

namespace sc::cli {
namespace {
// Filled only during static initialisation, read-only afterwards.
std::vector<CommandSpec>& registry() {
  static std::vector<CommandSpec> commands;
  return commands;
}
}  // namespace

CommandRegistration::CommandRegistration(CommandSpec spec) { registry().push_back(std::move(spec)); }

std::vector<CommandSpec> registered_commands() {
  auto commands = registry();
  std::sort(commands.begin(), commands.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return commands;
}

}  // namespace sc::cli
