// skillcoach diagnose --task T [--model FILE] TRIAL.json...: the learner's skills, expertise (Alg. 2),
// weakest skills and individualized drills (Alg. 3) as JSON; --png DIR also draws each drill's ghost path.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/parking_view/parking_trial_image.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"
#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/writing_trial_image.hpp"
#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/tasks/diagnosis.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "teaching/tasks/writing_drill_projector.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc::cli {
namespace {

struct DiagnoseArgs {
  TaskKind task = TaskKind::parking;
  std::string model;
  std::string png_dir;
  std::string out;
  unsigned long long seed = 0;
  std::optional<ExpertiseMode> expertise;  // default: the task's learners_expertise()
  std::vector<std::string> trials;
};

std::string drill_caption(const TaskKit& kit, const PlayableDrill& drill, std::size_t index) {
  std::string caption = "drill " + std::to_string(index + 1) + " for skill " + std::to_string(drill.plan.target_skill) +
                        " (" + kit.describe_skill(drill.plan.target_skill) + "), skills";
  for (int m : drill.plan.ngram) caption += " " + std::to_string(m);
  if (drill.plan.repetitions > 1) caption += " x" + std::to_string(drill.plan.repetitions);
  return caption;
}

void write_drill_pngs(TaskKind task, const TaskKit& kit, const Diagnosis& diagnosis, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::unique_ptr<GlContext> context;
  for (std::size_t i = 0; i < diagnosis.drills.size(); ++i) {
    const PlayableDrill& drill = diagnosis.drills[i];
    const std::filesystem::path file = dir / ("drill_" + std::to_string(i + 1) + ".png");
    if (task == TaskKind::parking) {
      // The drill trial drawn as a trail, its ghost path as the ribbon to follow.
      const ParkingTrial trial = parse_parking_trial(kit.drill_trial(drill), "drill");
      const ParkingPath ghost = simulate_parking_path(trial);
      if (!context) context = create_offscreen_context_from_env(1280, 720);
      ParkingTrialImageOptions options;
      options.expert = &ghost;
      write_png(file, render_parking_trial_image(*context, trial, options));
    } else {
      writing_view::WritingScene scene;
      scene.ribbon = WritingDrillProjector::drill_trace(drill);
      scene.caption = drill_caption(kit, drill, i);
      write_png(file, writing_view::render_writing_scene_image(scene, 1000, 600));
    }
    std::fprintf(stderr, "%s: %s\n", file.string().c_str(), drill_caption(kit, drill, i).c_str());
  }
}

// Each file is parsed with its own name before the diagnosis: a problem then names the file and the whole
// JSON path ($.scenario.heading0, not "trial: $.heading0"), and a writing trace capped at its point limit
// gets the documented warning.
void check_trial_file(TaskKind task, const Json& doc, const std::string& file) {
  if (task == TaskKind::parking) {
    parse_parking_trial(doc, file);
    return;
  }
  for (const auto& warning : writing::parse_writing_trial(doc, file).warnings)
    std::fprintf(stderr, "skillcoach: warning: %s\n", warning.c_str());
}

int run(const DiagnoseArgs& args) {
  std::vector<Json> trials;
  for (const std::string& file : args.trials) {
    trials.push_back(read_json_file(file));
    check_trial_file(args.task, trials.back(), file);
  }
  const std::unique_ptr<TaskKit> kit = make_task_kit(args.task, args.model);
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  Diagnosis diagnosis;
  try {
    diagnosis = diagnose_trials(*kit, trials, args.seed, args.expertise.value_or(kit->learners_expertise()));
  } catch (const InputError& e) {
    // "trial 2: ..." -> name the file instead.
    const std::string message = e.what();
    for (std::size_t i = 0; i < args.trials.size(); ++i) {
      const std::string prefix = "trial " + std::to_string(i) + ": ";
      if (message.rfind(prefix, 0) == 0) throw InputError(args.trials[i], message.substr(prefix.size()));
    }
    throw;
  }
  Json doc = diagnosis_json(*kit, diagnosis);
  for (std::size_t i = 0; i < args.trials.size(); ++i) doc["trials"][i]["file"] = args.trials[i];
  if (!args.png_dir.empty()) write_drill_pngs(args.task, *kit, diagnosis, args.png_dir);
  if (args.out.empty())
    std::printf("%s\n", doc.dump(1).c_str());
  else
    write_json_file(args.out, doc);
  return 0;
}

CommandRunner setup_diagnose(CLI::App& sub) {
  auto args = std::make_shared<DiagnoseArgs>();
  add_task_option(sub, args->task)->required();
  sub.add_option("--model", args->model,
                 "CompILE model file (default: assets/models/<task>.pt, else the time heuristic)");
  sub.add_option("--seed", args->seed, "Seed of the drills' random expert segments (default 0)");
  sub.add_option("--expertise", args->expertise,
                 "alg2: the paper's Alg. 2 (skills missing from the learner's trials); quality-aware: Alg. 2 plus "
                 "how well each skill was done (docs/skills.md). Default: the trainer's for the task (parking alg2, "
                 "writing quality-aware)")
      ->transform(CLI::CheckedTransformer(expertise_modes_by_name()));
  sub.add_option("--png", args->png_dir, "Directory to draw each drill's ghost path into (drill_N.png)");
  sub.add_option("--out", args->out, "Write the JSON here instead of standard output");
  sub.add_option("trials", args->trials, "Trial files of one learner (JSON)")->required();
  return [args] { return run(*args); };
}

const CommandRegistration kDiagnoseCommandRegistration{
    {"diagnose", "Find a learner's weakest skills in their trials and build drills for them",
     "skillcoach diagnose --task parking --png drills/ pretest1.json pretest2.json", setup_diagnose}};

}  // namespace
}  // namespace sc::cli
