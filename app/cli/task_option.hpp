#pragma once
// `--task parking|writing` for every subcommand: the text becomes a TaskKind where it enters (CLI11 maps it
// and refuses anything else with one error line, exit 2), so commands compare kinds, never strings.
#include <CLI/CLI.hpp>

#include <string>

#include "engine/core/task_kind.hpp"

namespace sc::cli {

CLI::Option* add_task_option(CLI::App& sub, TaskKind& task, const std::string& help = "parking or writing");

}  // namespace sc::cli
