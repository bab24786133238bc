// skillcoach expert-pool --task parking [--region study-corner]: (re)generates a shipped parking expert pool
// (assets/experts/parking_pool.json, parking_pool_study_corner.json) that ParkingKit loads at start instead
// of planning ~100 scenarios.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_kit.hpp"

namespace sc::cli {
namespace {

struct PoolArgs {
  TaskKind task = TaskKind::parking;
  int count = ParkingPoolOptions{}.count;
  unsigned long long seed = ParkingPoolOptions{}.seed;
  std::string region = "whole-lot";
  std::string out;
};

int run(const PoolArgs& args) {
  if (args.task != TaskKind::parking)
    throw InputError("--task", "only the parking pool is cached (writing pools are built from the stroke files)");
  const ParkingPoolOptions options{args.count, args.seed, parse_goal_region(args.region, "--region")};
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<ParkingTrial> trials = generate_parking_pool(options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::filesystem::path out =
      args.out.empty() ? default_parking_pool_file(options.region) : std::filesystem::path(args.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  write_json_file(out, parking_pool_json(options, trials), 0);
  int parked = 0;
  for (const ParkingTrial& t : trials) parked += t.success.value_or(false);
  std::printf("%s: %d expert trials (seed %llu, %s), %d parked, planned in %.1f s\n", out.string().c_str(), args.count,
              args.seed, args.region.c_str(), parked, seconds);
  return parked == args.count ? 0 : 1;
}

CommandRunner setup_expert_pool(CLI::App& sub) {
  auto args = std::make_shared<PoolArgs>();
  add_task_option(sub, args->task, "Task whose expert pool to generate (parking)")->required();
  sub.add_option("--count", args->count, "Scenarios in the pool")->capture_default_str()->check(CLI::Range(1, 100000));
  sub.add_option("--seed", args->seed, "Seed of the pool's scenarios")->capture_default_str();
  sub.add_option("--region", args->region, "Goal spots: whole-lot, or study-corner (the paper's user study)")
      ->capture_default_str();
  sub.add_option("--out", args->out,
                 "File to write (default: assets/experts/parking_pool.json, or parking_pool_study_corner.json)");
  return [args] { return run(*args); };
}

const CommandRegistration kExpertPoolCommandRegistration{
    {"expert-pool", "Generate the cached expert pool the parking teaching flow starts from",
     "skillcoach expert-pool --task parking --count 100 --seed 0", setup_expert_pool}};

}  // namespace
}  // namespace sc::cli
