// skillcoach evaluate-skills --task T --model FILE [--count N] [--seed S]: segments freshly generated expert
// demonstrations (a seed other than the model's training seed) with the model and prints the quality
// report (teaching/tasks/skill_quality.hpp) as JSON: writing boundary precision/recall/F1 against the
// true character boundaries, parking skill purity, per-skill usage, and the action reconstruction error.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/command_registry.hpp"
#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/skill_quality.hpp"
#include "teaching/tasks/skill_training_data.hpp"

namespace sc::cli {
namespace {

struct EvaluateArgs {
  std::string task;
  std::string model;
  int count = 200;
  std::optional<unsigned long long> seed;
  bool details = false;
};

// One entry per demonstration: what it is, its true boundaries (writing) and the predicted segments, so a
// researcher can see *where* a model goes wrong, not only the totals.
Json demo_details(const SkillDataSet& data, const std::vector<Segmentation>& segmentations) {
  Json out = Json::array();
  for (std::size_t i = 0; i < data.demos.size(); ++i) {
    Json segments = Json::array();
    for (const SkillSegment& s : segmentations[i].segments) segments.push_back(Json::array({s.skill, s.begin, s.end}));
    out.push_back({{"label", data.demos[i].label},
                   {"steps", data.demos[i].steps.length()},
                   {"true_boundaries", data.demos[i].true_boundaries},
                   {"segments", std::move(segments)}});
  }
  return out;
}

int run(const EvaluateArgs& args) {
  const int state_dim = args.task == "parking" ? kParkingStateDim : writing::kWritingStateDim;
  const CompileModel model = CompileModel::load(args.model, args.task, state_dim, 2);
  // Held-out data: the training data was generated from the model's own seed.
  const std::uint64_t seed = args.seed ? *args.seed : model.config().seed + 1;
  if (seed == model.config().seed)
    throw InputError("--seed", std::to_string(seed) + " is the seed the model was trained with; pick another");
  std::fprintf(stderr, "evaluate-skills: generating %d %s demonstrations (seed %llu)...\n", args.count,
               args.task.c_str(), static_cast<unsigned long long>(seed));
  const SkillDataSet data = generate_task_demos(args.task, args.count, seed);
  const std::vector<StepSequence> steps = data.steps();
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Segmentation> segmentations = model.segment(steps);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Json report = skill_quality_report(data, segmentations);
  report["model"] = args.model;
  report["seed"] = seed;
  report["action_reconstruction_error"] = model.action_reconstruction_error(steps);
  report["segmentation_seconds"] = seconds;
  if (args.details) report["demos"] = demo_details(data, segmentations);
  std::printf("%s\n", report.dump(1).c_str());
  return 0;
}

CommandRunner setup(CLI::App& sub) {
  auto args = std::make_shared<EvaluateArgs>();
  sub.add_option("--task", args->task, "parking or writing")->required()->check(CLI::IsMember({"parking", "writing"}));
  sub.add_option("--model", args->model, "CompILE model file")->required();
  sub.add_option("--count", args->count, "Demonstrations to generate")->capture_default_str()->check(CLI::Range(1, 100000));
  sub.add_option("--seed", args->seed, "Seed of the generated demonstrations (default: the model's seed + 1)");
  sub.add_flag("--details", args->details,
               "Also list every demonstration: its true boundaries and the predicted [skill, start, end] segments");
  return [args] { return run(*args); };
}

const CommandRegistration kReg{{"evaluate-skills", "Measure a CompILE model's segmentation quality on fresh expert data",
                                "skillcoach evaluate-skills --task writing --model assets/models/writing.pt --count 200",
                                setup}};

}  // namespace
}  // namespace sc::cli
