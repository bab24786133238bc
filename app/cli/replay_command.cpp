// skillcoach replay --task parking FILE.json: re-simulates a trial's actions from its scenario and prints
// one JSON line per control step, then a summary line.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "engine/parking/parking_replay.hpp"
#include "engine/parking/parking_trial.hpp"

namespace sc::cli {
namespace {

struct ReplayArgs {
  TaskKind task = TaskKind::parking;
  std::string file;
};

int replay_parking(const std::string& file) {
  const ParkingTrial trial = read_parking_trial(file);
  const ParkingReplay replay = replay_parking_trial(trial);
  for (const auto& s : replay.steps) {
    std::printf("{\"t\":%d,\"x\":%.6f,\"y\":%.6f,\"heading\":%.6f,\"speed\":%.6f,\"reward\":%.6f,\"success\":%s}\n",
                s.t, s.vehicle.x, s.vehicle.y, s.vehicle.heading, s.vehicle.speed, s.reward,
                s.success ? "true" : "false");
  }
  std::printf(
      "{\"summary\":true,\"steps\":%zu,\"return\":%.6f,\"success_step\":%s,\"collision\":%s,\"ignored_actions\":%d}\n",
      replay.steps.size(), replay.total_return,
      replay.success_step > 0 ? std::to_string(replay.success_step).c_str() : "null",
      replay.collision ? "true" : "false", replay.ignored_actions);
  return 0;
}

CommandRunner setup_replay(CLI::App& sub) {
  auto args = std::make_shared<ReplayArgs>();
  add_task_option(sub, args->task, "Task of the trial file (parking; writing trials are not simulated)")->required();
  sub.add_option("file", args->file, "Trial file (JSON)")->required();
  return [args] {
    if (args->task == TaskKind::parking) return replay_parking(args->file);
    throw InputError("--task", "replay simulates parking trials only (a writing trial has nothing to re-simulate)");
  };
}

const CommandRegistration kReplayCommandRegistration{{"replay",
                                                      "Re-simulate a trial file and print the states step by step",
                                                      "skillcoach replay --task parking trial.json", setup_replay}};

}  // namespace
}  // namespace sc::cli
