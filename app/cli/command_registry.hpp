#pragma once
// Headless subcommands register themselves (like Box2D's samples): each app/cli/<name>_command.cpp
// defines one `static const CommandRegistration` and main() wires every registered command into CLI11.
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sc::cli {

// Adds the command's options to `sub` and returns the function that runs it (returns the exit code).
// Exit codes: 0 success, 1 the work itself failed (e.g. a target not met), 2 bad input or usage.
using CommandRunner = std::function<int()>;
using CommandSetup = std::function<CommandRunner(CLI::App& sub)>;

struct CommandSpec {
  std::string name;
  std::string description;  // one line for --help
  std::string example;      // a full example command line, shown in --help
  CommandSetup setup;
};

class CommandRegistration {
 public:
  explicit CommandRegistration(CommandSpec spec);
};

// All registered commands, sorted by name.
std::vector<CommandSpec> registered_commands();

}  // namespace sc::cli
