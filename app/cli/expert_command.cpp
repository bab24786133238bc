// skillcoach expert --task parking: plans scenarios with the planning expert and reports how well it did.
// skillcoach expert --task writing: the writing expert is the gold trajectory of a word; writes the gold
// trials of words from the reference's generator (the data train-skills generates), e.g. for
// `train-skills --data` or `segment --png`.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/writing/word_generator.hpp"
#include "engine/writing/word_trajectory.hpp"
#include "engine/writing/writing_trial.hpp"

namespace sc::cli {
namespace {

struct ExpertArgs {
  TaskKind task = TaskKind::parking;
  int count = 100;
  unsigned long long seed = 0;
  std::string variant = "classic";
  double reverse_in = 0.0;
  std::string out_dir;
  std::string scenario_file;
};

// A trial file (has "task") or a bare scenario object (has "heading0").
ParkingScenario read_scenario(const std::string& file) {
  const Json doc = read_json_file(file);
  const JsonView root(doc, file);
  if (root.is_object() && root.find("task")) return parse_parking_trial(doc, file).scenario;
  return parse_parking_scenario(root);
}

void print_plan_summary(const ParkingPlan& plan) {
  std::printf(
      "{\"success\":%s,\"success_step\":%d,\"steps\":%zu,\"return\":%.6f,\"collision\":%s,\"planning_ms\":%.2f}\n",
      plan.success ? "true" : "false", plan.success_step, plan.actions.size(), plan.total_return(),
      plan.collision ? "true" : "false", plan.planning_ms);
}

int run_one(const ExpertArgs& args) {
  const ParkingScenario scenario = read_scenario(args.scenario_file);
  const ParkingPlan plan = ParkingExpert().plan(scenario);
  const ParkingTrial trial = plan.to_trial(scenario);
  std::printf("%s\n", parking_trial_to_json(trial).dump().c_str());
  print_plan_summary(plan);
  if (!args.out_dir.empty()) {
    std::filesystem::create_directories(args.out_dir);
    write_parking_trial(std::filesystem::path(args.out_dir) / "expert_plan.json", trial);
  }
  return plan.success ? 0 : 1;
}

int run_many(const ExpertArgs& args) {
  const LotVariant variant = parse_lot_variant(args.variant, "--variant");
  if (args.count < 1) throw InputError("--count", "must be at least 1");
  if (!args.out_dir.empty()) std::filesystem::create_directories(args.out_dir);
  Rng rng(args.seed);
  const ParkingExpert expert;
  int successes = 0, collisions = 0;
  long success_steps = 0;
  double total_return = 0.0;
  std::vector<double> times;
  for (int i = 0; i < args.count; ++i) {
    const ParkingScenario scenario = sample_parking_scenario(rng, variant, args.reverse_in);
    const ParkingPlan plan = expert.plan(scenario);
    successes += plan.success;
    collisions += plan.collision;
    if (plan.success) success_steps += plan.success_step;
    total_return += plan.total_return();
    times.push_back(plan.planning_ms);
    if (!args.out_dir.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "expert_%05d.json", i);
      write_parking_trial(std::filesystem::path(args.out_dir) / name, plan.to_trial(scenario));
    }
  }
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  std::printf("parking expert, %d %s scenarios (seed %llu%s)\n", args.count, args.variant.c_str(), args.seed,
              args.reverse_in > 0 ? (", reverse-in probability " + std::to_string(args.reverse_in)).c_str() : "");
  std::printf("  success rate            %.1f%% (%d/%d)\n", 100.0 * successes / args.count, successes, args.count);
  std::printf("  mean return             %.3f\n", total_return / args.count);
  std::printf("  mean steps to success   %.2f\n", successes ? static_cast<double>(success_steps) / successes : 0.0);
  std::printf("  collisions              %d\n", collisions);
  std::printf("  planning time (CPU)     median %.1f ms, max %.1f ms\n", median, times.back());
  if (!args.out_dir.empty()) std::printf("  trial files             %s/expert_*.json\n", args.out_dir.c_str());
  return 0;
}

int run_writing(const ExpertArgs& args) {
  if (args.count < 1) throw InputError("--count", "must be at least 1");
  if (args.out_dir.empty())
    throw InputError("--out", "the writing expert needs a directory to write its gold trials to");
  std::filesystem::create_directories(args.out_dir);
  const std::vector<std::string> words = writing::classic_words(args.count, args.seed);
  const writing::GlyphSet glyphs =
      writing::GlyphSet::load(writing::AlphabetKind::Classic, writing::omniglot_data_dir());
  std::size_t points = 0;
  for (int i = 0; i < args.count; ++i) {
    const std::string& word = words[static_cast<std::size_t>(i)];
    const writing::WordTrajectory gold = writing::build_word_trajectory(glyphs, word);
    const writing::WritingTrial trial = writing::gold_trial({word, writing::AlphabetKind::Classic, {}}, gold);
    points += trial.points.size();
    char name[32];
    std::snprintf(name, sizeof name, "expert_%05d.json", i);
    writing::write_writing_trial(std::filesystem::path(args.out_dir) / name, trial);
  }
  std::printf("writing expert, %d classic words (seed %llu): gold trajectories, %.0f pen points per word on average\n",
              args.count, args.seed, static_cast<double>(points) / args.count);
  std::printf("  trial files             %s/expert_*.json\n", args.out_dir.c_str());
  return 0;
}

CommandRunner setup_expert(CLI::App& sub) {
  auto args = std::make_shared<ExpertArgs>();
  add_task_option(sub, args->task, "parking (plans scenarios) or writing (gold trials of generated words, needs --out)")
      ->required();
  sub.add_option("--count", args->count, "Number of random scenarios (default 100)");
  sub.add_option("--seed", args->seed, "Seed of the scenario sampler (default 0)");
  sub.add_option("--variant", args->variant, "Lot variant: classic (the paper's empty lot) or parked");
  sub.add_option("--reverse-in", args->reverse_in, "Probability of a reverse-in goal (default 0)")
      ->check(CLI::Range(0.0, 1.0));
  sub.add_option("--out", args->out_dir, "Directory to write one trial file per scenario (source \"expert\")");
  sub.add_option("--scenario", args->scenario_file, "Plan one scenario from a trial file or a bare scenario object");
  return [args] {
    if (args->task == TaskKind::writing) {
      if (!args->scenario_file.empty() || args->variant != "classic" || args->reverse_in > 0.0)
        throw InputError("--task writing", "--scenario, --variant and --reverse-in are parking options");
      return run_writing(*args);
    }
    return args->scenario_file.empty() ? run_many(*args) : run_one(*args);
  };
}

const CommandRegistration kExpertCommandRegistration{
    {"expert", "Plan parking scenarios with the expert and summarise them, or write writing gold trials",
     "skillcoach expert --task parking --count 1000 --seed 1 --variant parked", setup_expert}};

}  // namespace
}  // namespace sc::cli
