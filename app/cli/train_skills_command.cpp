// skillcoach train-skills --task parking|writing [--data DIR] [--iterations N] [--seed S] [--set K=V] --out FILE:
// trains the task's CompILE model at the paper's defaults (CompileConfig::defaults_for) on the expert's
// demonstrations (generated when no --data is given), holding out 10 % for early stopping, and writes the
// model file plus its JSON sidecar (for writing with the noise floor calibrated with the model; generated writing
// words keep the restart whose skills agree most with the same words by other hands). Same seed
// and data on the same machine -> the same model bytes.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "app/core/training_progress_bar.hpp"
#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "teaching/learners/parking/augmented_parking_demos.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/compile_trainer.hpp"
#include "teaching/tasks/skill_training_data.hpp"
#include "teaching/tasks/writing_cross_hand.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_noise_floor.hpp"

namespace sc::cli {
namespace {

constexpr double kValidFraction = 0.1;

struct TrainArgs {
  TaskKind task = TaskKind::parking;
  std::string data;
  std::string out;
  int demos = 1000;
  int iterations = -1;  // -1: the task's default
  unsigned long long seed = 0;
  std::vector<std::string> overrides;              // --set key=value
  bool fix_boundaries = false;                     // diagnostic: boundaries fixed at the true symbol edges
  int augment = 0;                                 // realistic copies per demonstration (0 = the expert's only)
  std::string augment_drawers = "training";        // writing: "training" (paper's + drawers 1-10) or "paper"
  bool augment_mouse = false;                      // writing: copies are also mouse-sampled
  int augment_other_hands = 0;                     // writing: copies by drawers 1-10, boundaries carried by alignment
  bool augment_keyed = false;                      // parking: one more copy per plan, keyboard keys on clean states
  int noise_floor_learners = kNoiseFloorLearners;  // writing: learners calibrating the recorded floor (0: none)
  std::string restart_choice;                      // "nll" or "cross-hand"; empty: the task's (writing: cross-hand)
  bool save_every_restart = false;                 // research: every restart's model as <out>.restart<k>.pt
  int restart_check_words = RestartCrossHandCheck{}.words;  // words of the cross-hand check
};

// The check writes generated classic words, so it is the default only for models of them; the diagnostic
// --fix-boundaries model is not for segmenting.
bool chooses_by_cross_hand(const TrainArgs& args) {
  if (args.restart_choice.empty()) return args.task == TaskKind::writing && args.data.empty() && !args.fix_boundaries;
  return args.restart_choice == "cross-hand";
}

std::string restart_file(const std::string& out, int restart) {
  return out + ".restart" + std::to_string(restart) + ".pt";
}

// Scores each restart's model for choose_restart (writing: cross-hand consistency, writing_cross_hand.hpp; only
// when there are restarts to choose from) and, for research, saves it; an empty review when neither is wanted.
CompileTrainer::RestartReview restart_review(const TrainArgs& args, const ModelProvenance& provenance, bool score) {
  if (!score && !args.save_every_restart) return {};
  const RestartCrossHandCheck check = restart_cross_hand_check(args.seed, args.restart_check_words);
  // Written and aligned once, on the first restart's review; every restart is only segmented on them.
  auto words = std::make_shared<std::optional<CrossHandWords>>();
  return [=](const CompileModel& model, int restart) {
    double kappa = std::numeric_limits<double>::quiet_NaN();
    if (score) {
      // A non-owning pointer: the extractor lives only inside this call, the model outlives it.
      const CompileExtractor extractor(std::shared_ptr<const CompileModel>(std::shared_ptr<void>(), &model));
      std::fprintf(stderr, "restart %d: checking its skills on %d words by other hands...\n", restart, check.words);
      if (!*words) words->emplace(restart_check_words(ClassicDrawerGlyphs::load(), check));
      kappa = restart_cross_hand_score(extractor, **words);
      std::fprintf(stderr, "restart %d: %s %.3f\n", restart, check.describe().c_str(), kappa);
    }
    if (args.save_every_restart) model.save(restart_file(args.out, restart), provenance);
    return kappa;
  };
}

// Applies `--set key=value` to the task's defaults through the config's JSON form, so every field has one
// spelling (the sidecar's) and the usual range checks (CompileConfig::validate). Numbers are read as JSON.
CompileConfig with_overrides(CompileConfig config, const std::vector<std::string>& overrides) {
  Json doc = to_json(config, /*every_field=*/true);
  for (const std::string& item : overrides) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq);
    if (eq == std::string::npos || !doc.contains(key) || key == "task")
      throw InputError("--set " + item, "expected key=value with a key of the model config (e.g. prior_rate=10)");
    const std::string value = item.substr(eq + 1);
    doc[key] = doc[key].is_string() ? Json(value) : parse_json_text(value, "--set " + item);
  }
  CompileConfig out = compile_config_from_json(JsonView(doc, "--set"));
  out.validate("--set");
  return out;
}

std::string run_and_read(const std::string& command) {
  std::string text;
  if (std::FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    if (pclose(pipe) != 0) return {};
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

// The checkout's revision ("<hash>" or "<hash>-dirty" with uncommitted changes to tracked files), or empty
// when the assets do not live in a git checkout.
std::string git_revision() {
  const std::string dir = asset_dir().parent_path().string();
  const std::string git = "git -C '" + dir + "' ";
  const std::string hash = run_and_read(git + "rev-parse --short=12 HEAD 2>/dev/null");
  if (hash.empty()) return {};
  const std::string changes = run_and_read(git + "status --porcelain --untracked-files=no 2>/dev/null");
  return changes.empty() ? hash : hash + "-dirty";
}

SkillDataSet generate_augmented_demos(const TrainArgs& args) {
  if (args.task == TaskKind::parking)
    return generate_augmented_parking_demos(args.demos, args.augment, args.seed, args.augment_keyed);
  const AugmentDrawers drawers =
      args.augment_drawers == "paper" ? AugmentDrawers::PaperOnly : AugmentDrawers::PaperAndTraining;
  return generate_augmented_writing_demos(args.demos, args.augment, args.seed,
                                          {drawers, args.augment_mouse, args.augment_other_hands});
}

// Quality-aware expertise's noise floor belongs to the model that segments (writing_noise_floor.hpp): calibrated
// with the model just written and recorded in its sidecar (~1 min).
void record_writing_noise_floor(const std::string& out, int learners) {
  std::fprintf(stderr, "writing: calibrating the noise floor on %d noise-only learners (seed %llu)...\n", learners,
               static_cast<unsigned long long>(kNoiseFloorSeed));
  const WritingKit kit(std::make_shared<CompileExtractor>(CompileExtractor::load(out, "writing")), "");
  const NoiseFloorCalibration calibration = calibrate_writing_noise_floor(kit, learners, kNoiseFloorSeed);
  record_noise_floor(out, calibration, kNoiseFloorSeed);
  std::printf("%s: noise floor %.3f recorded in its sidecar\n", out.c_str(), calibration.floor());
}

int run(const TrainArgs& args) {
  CompileConfig config = CompileConfig::defaults_for(args.task);
  config.seed = args.seed;
  if (args.iterations >= 0) config.iterations = args.iterations;
  config = with_overrides(config, args.overrides);
  std::fprintf(stderr, "%s: %s demonstrations...\n", std::string(to_string(args.task)).c_str(),
               args.data.empty() ? "generating" : "reading");
  if (args.augment_mouse && (args.task != TaskKind::writing || args.augment == 0))
    throw InputError("--augment-mouse", "only for writing with --augment");
  if (args.augment_other_hands > 0 && (args.task != TaskKind::writing || args.augment == 0))
    throw InputError("--augment-other-hands", "only for writing with --augment");
  if (chooses_by_cross_hand(args) && args.task != TaskKind::writing)
    throw InputError("--restart-choice cross-hand", "only for writing");
  if (args.augment_keyed && (args.task != TaskKind::parking || args.augment == 0))
    throw InputError("--augment-keyed", "only for parking with --augment");
  if (args.augment > 0 && !args.data.empty())
    throw InputError("--augment", "only for generated demonstrations (without --data)");
  const SkillDataSet data = args.augment > 0    ? generate_augmented_demos(args)
                            : args.data.empty() ? generate_task_demos(args.task, args.demos, args.seed)
                                                : read_task_demos(args.task, args.data);
  const DataSplit split = split_demos(data, kValidFraction, args.seed);
  std::fprintf(stderr, "%s: %zu training and %zu validation trajectories (%s)\n",
               std::string(to_string(args.task)).c_str(), split.train.size(), split.valid.size(),
               data.description.c_str());

  CompileTrainer trainer(config);
  if (args.fix_boundaries) {
    for (const SkillDemo& demo : data.demos)
      if (demo.true_boundaries.empty())
        throw InputError("--fix-boundaries", "demonstration " + demo.label +
                                                 " has no known boundaries (only generated writing words have them)");
    trainer.fix_boundaries(split.train_boundaries, split.valid_boundaries);
  }
  if (!split.train_warm_boundaries.empty()) trainer.warm_start_at(split.train_warm_boundaries, split.train_warm_units);
  ModelProvenance provenance;
  provenance.data_description = data.description + "; " + std::to_string(split.train.size()) + " train / " +
                                std::to_string(split.valid.size()) + " validation (seed " + std::to_string(args.seed) +
                                ")";
  if (args.fix_boundaries) provenance.data_description += "; DIAGNOSTIC: boundaries fixed at the true symbol edges";
  provenance.git_revision = git_revision();
  const bool score_restarts = chooses_by_cross_hand(args) && config.restarts > 1;
  trainer.review_restarts_with(restart_review(args, provenance, score_restarts));
  TrainingProgressBar bar(stderr);
  const CompileModel model = trainer.train(split.train, split.valid, [&](const TrainingProgress& p) { bar.update(p); });
  bar.finish();
  const TrainingSummary& summary = trainer.summary();

  provenance.metrics = summary.to_json();
  if (score_restarts)
    provenance.metrics["restart_score_kind"] = restart_cross_hand_check(args.seed, args.restart_check_words).describe();
  provenance.metrics["fixed_boundaries"] = args.fix_boundaries;
  // With fixed boundaries the boundary head never learned, so an error measured with its boundaries would
  // describe nothing; the validation NLL above (measured at the fixed boundaries) is the figure to read.
  provenance.metrics["valid_action_reconstruction_error"] =
      split.valid.empty() || args.fix_boundaries ? Json(nullptr) : Json(model.action_reconstruction_error(split.valid));
  model.save(args.out, provenance);
  std::printf("%s: %d iterations in %.1f s (best %d, valid NLL %.4g%s), %d parameters\n", args.out.c_str(),
              summary.iterations_run, summary.seconds, summary.best_iteration, summary.best_valid_nll,
              summary.stopped_early ? ", stopped early" : "", model.parameter_count());
  if (args.task == TaskKind::writing && !args.fix_boundaries && args.noise_floor_learners > 0)
    record_writing_noise_floor(args.out, args.noise_floor_learners);
  return 0;
}

CommandRunner setup_train_skills(CLI::App& sub) {
  auto args = std::make_shared<TrainArgs>();
  add_task_option(sub, args->task)->required();
  sub.add_option("--data", args->data, "Folder of trial files to train on (default: generate expert demonstrations)");
  sub.add_option("--demos", args->demos, "Demonstrations to generate when no --data is given")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  sub.add_option("--iterations", args->iterations, "Maximum passes over the training data (default: the task's)")
      ->check(CLI::Range(0, 1000000));
  sub.add_option("--seed", args->seed, "Seed of the generated data, the split and the training")->capture_default_str();
  sub.add_option("--set", args->overrides,
                 "Override a model setting of the task's defaults, e.g. --set prior_rate=10 "
                 "(keys as in the model's JSON sidecar; repeatable)");
  sub.add_flag("--fix-boundaries", args->fix_boundaries,
               "Diagnostic (generated writing words): fix every boundary at the true symbol edges and train only the "
               "latents and the decoder, to measure the validation NLL CompILE's objective gives the letter "
               "segmentation; the model is not for segmenting");
  sub.add_option("--augment", args->augment,
                 "Add this many realistic copies of each generated demonstration. Writing: letters by the paper's and "
                 "drawers 1-10, copies with wobble and affine variation that inherit the clean word's repetition "
                 "boundaries for the warm start; parking: novice drives of each plan (noise, delay, device) "
                 "(docs/skills.md \"Robustness\")")
      ->check(CLI::Range(0, 20));
  sub.add_option("--augment-drawers", args->augment_drawers,
                 "Writing with --augment: whose letters the words are made of, \"training\" (the paper's drawer and "
                 "drawers 1-10) or \"paper\" (the paper's drawer only, so letters repeat exactly)")
      ->check(CLI::IsMember({"training", "paper"}))
      ->capture_default_str();
  sub.add_flag("--augment-mouse", args->augment_mouse,
               "Writing with --augment: the copies are also read as a mouse reports them (speed, screen grid, "
               "hesitations); their inherited boundaries move with the readings");
  sub.add_option("--augment-other-hands", args->augment_other_hands,
                 "Writing with --augment: this many more copies of each word with letters by drawers 1-10, the clean "
                 "word's repetition boundaries carried to them by aligning the two traces (docs/skills.md \"Copies by "
                 "other hands\")")
      ->check(CLI::Range(0, 20));
  sub.add_flag("--augment-keyed", args->augment_keyed,
               "Parking with --augment: each plan also gets a copy with keyboard keys for its actions on the clean "
               "states (docs/skills.md \"Why the keyboard rows disagree\")");
  sub.add_option("--noise-floor-learners", args->noise_floor_learners,
                 "Writing: noise-only learners on whom the trained model's noise floor is calibrated and recorded in "
                 "its sidecar (0: record none; docs/skills.md \"A fourth change: a noise floor\")")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  sub.add_option("--restart-choice", args->restart_choice,
                 "Which restart to keep among those whose warm start separated its units: \"nll\" (lowest validation "
                 "NLL) or \"cross-hand\" (writing: most consistent with the same words by drawers 1-10; "
                 "docs/skills.md \"Choosing the restart by cross-hand consistency\"). Default: cross-hand for "
                 "generated writing words, else nll")
      ->check(CLI::IsMember({"nll", "cross-hand"}));
  sub.add_option("--restart-check-words", args->restart_check_words,
                 "Words the cross-hand check of --restart-choice writes (fewer: quicker, less sure)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  sub.add_flag("--save-every-restart", args->save_every_restart,
               "Research: also write every restart's model as <out>.restart<k>.pt (plus its JSON sidecar)");
  sub.add_option("--out", args->out, "Model file to write (plus <file>.json)")->required();
  return [args] { return run(*args); };
}

const CommandRegistration kTrainSkillsCommandRegistration{
    {"train-skills", "Train a task's CompILE skill model on expert demonstrations",
     "skillcoach train-skills --task writing --seed 3 --demos 333 --augment 2 --augment-drawers paper --augment-mouse "
     "--augment-other-hands 1 --set straight_through_latents=true --set warm_start_units=true "
     "--set warm_start_unit_weight=10 --out assets/models/writing.pt",
     setup_train_skills}};

}  // namespace
}  // namespace sc::cli
