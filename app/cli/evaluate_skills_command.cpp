// skillcoach evaluate-skills --task T (--model FILE | --time-heuristic) [--count N] [--seed S]
// [--robustness | --planted-weaknesses [--learners N] | --noise-floor [--learners N] | --realistic-drivers]:
// segments freshly
// generated expert demonstrations (a seed other than the model's training seed) with the model, or with the
// paper's Time Heuristic baseline as the yardstick, and prints the quality report
// (teaching/tasks/skill_quality.hpp) as JSON: writing boundary precision/recall/F1 against the true character
// boundaries, parking skill purity, per-skill usage, and (models only) the action reconstruction error.
// For writing, --robustness prints the same model's figures on realistic learners (writing_robustness.hpp)
// and --planted-weaknesses Alg. 2's recovery of a badly written letter (writing_planted_weakness.hpp), as tables;
// --noise-floor calibrates quality-aware expertise's noise floor on the noise-only learners
// (execution_noise_floor.hpp).
// --realistic-drivers (parking): the skills of realistic drivers' copies of the drives against the clean
// drives' (docs/skills.md, "Robustness on realistic learners"), open loop, following the path and standing still at
// the start or end, each copy read from its first to its last moving step as the parking kit reads it
// (--read-whole-drives: read whole, as before 2026-12-05). --readout-phases P
// reads the model at P phases of its resampling instead of the file's number (phase_vote.hpp), for every table.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "engine/writing/word_generator.hpp"
#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/learners/parking/drive_skill_agreement.hpp"
#include "teaching/learners/parking/path_follower.hpp"
#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/execution_noise_floor.hpp"
#include "teaching/tasks/parking_drive_reading.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/skill_quality.hpp"
#include "teaching/tasks/skill_training_data.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "teaching/tasks/writing_cross_hand.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_noise_floor.hpp"
#include "teaching/tasks/writing_planted_weakness.hpp"
#include "teaching/tasks/writing_robustness.hpp"

namespace sc::cli {
namespace {

struct EvaluateArgs {
  TaskKind task = TaskKind::parking;
  std::string model;
  bool time_heuristic = false;
  int count = 200;
  std::optional<unsigned long long> seed;
  bool details = false;
  bool robustness = false;
  bool planted = false;
  bool own_hands = false;  // --planted-weaknesses: every learner writes in an unseen drawer's shapes
  bool noise_floor = false;
  bool record = false;  // --noise-floor: write the calibrated floor into the model's sidecar
  int learners = 20;
  ExpertiseMode expertise = ExpertiseMode::Alg2;
  bool realistic_drivers = false;
  ParkingDriveReading reading;
  std::optional<int> readout_phases;  // instead of the model file's (CompileConfig::readout_phases)
};

// The model as the command reads it: the file's, at --readout-phases when given.
std::shared_ptr<const CompileModel> load_model(const EvaluateArgs& args) {
  const int state_dim = args.task == TaskKind::parking ? kParkingStateDim : writing::kWritingStateDim;
  auto model =
      std::make_shared<CompileModel>(CompileModel::load(args.model, std::string(to_string(args.task)), state_dim, 2));
  if (args.readout_phases) model->set_readout_phases(*args.readout_phases);
  return model;
}

// Parking: the same held-out scenarios' expert drives driven by realistic drivers
// (teaching/learners/parking/drive_skill_agreement.hpp), one row per condition.
std::vector<ParkingTrial> held_out_drives(int count, std::uint64_t seed) {
  std::vector<ParkingTrial> drives;
  for (ParkingTrial& t : generate_parking_pool({count, seed}))
    if (t.success.value_or(false)) drives.push_back(std::move(t));
  return drives;
}

Json realistic_driver_rows(const SkillExtractor& extractor, const std::vector<ParkingTrial>& drives,
                           std::uint64_t seed) {
  std::vector<DriveCondition> conditions = standard_drive_conditions();
  for (DriveCondition& c : path_following_conditions()) conditions.push_back(std::move(c));  // appended: same draws
  for (DriveCondition& c : standing_start_conditions()) conditions.push_back(std::move(c));
  for (DriveCondition& c : keeps_trying_conditions()) conditions.push_back(std::move(c));
  for (DriveCondition& c : gentle_steering_key_conditions()) conditions.push_back(std::move(c));
  Json rows = Json::array();
  for (const AgreementRow& r : measure_drive_agreement(extractor, drives, conditions, seed)) {
    rows.push_back({{"condition", r.condition},
                    {"drives", r.drives},
                    {"steps", r.agreement.steps},
                    {"agreement", r.agreement.share()},
                    {"skill_presence", r.presence.share()},
                    {"still_parked", r.successes}});
    std::fprintf(stderr,
                 "  %-64s agreement %5.1f %%  skills present %5.1f %%  (%d steps, %d of %d drives still parked)\n",
                 r.condition.c_str(), 100.0 * r.agreement.share(), 100.0 * r.presence.share(), r.agreement.steps,
                 r.successes, r.drives);
  }
  return rows;
}

// How much room a driver has to correct: the expert's steps at the pedal's or the steering's limit.
Json limits_row(const std::vector<ParkingTrial>& drives) {
  const ActuatorLimits l = actions_at_limits(drives);
  const double n = std::max(l.steps, 1);
  std::fprintf(stderr, "  the expert's drives: pedal at its limit on %.1f %% of %d steps, steering on %.1f %%\n",
               100.0 * l.pedal / n, l.steps, 100.0 * l.steering / n);
  return {{"steps", l.steps}, {"pedal", l.pedal / n}, {"steering", l.steering / n}};
}

// The same drives with keyboard keys for actions on the clean motion (keyed_action_agreement).
double keyed_action_row(const SkillExtractor& extractor, const std::vector<ParkingTrial>& drives) {
  const StepAgreement a = keyed_action_agreement(extractor, drives);
  std::fprintf(stderr, "  %-64s agreement %5.1f %%  (%d steps)\n", "keyboard keys on the clean motion",
               100.0 * a.share(), a.steps);
  return a.share();
}

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

template <typename Segment>
std::pair<std::vector<Segmentation>, double> timed(Segment&& segment) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Segmentation> out = segment();
  return {std::move(out), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

// The model run() loaded (null with --time-heuristic) as the extractor the tables segment with.
std::shared_ptr<const SkillExtractor> evaluation_extractor(const EvaluateArgs& args,
                                                           const std::shared_ptr<const CompileModel>& model) {
  if (!model) return std::make_shared<TimeHeuristicExtractor>(CompileConfig::defaults_for(args.task).num_segments);
  return std::make_shared<CompileExtractor>(model);
}

// The writing kit the planted and noise-floor tables diagnose with: the model's recorded noise floor, as the app.
std::unique_ptr<WritingKit> evaluation_writing_kit(const EvaluateArgs& args,
                                                   const std::shared_ptr<const CompileModel>& model) {
  return make_writing_kit(evaluation_extractor(args, model), args.time_heuristic ? "" : args.model);
}

// The robustness table (writing): the model (or the time heuristic) on words by realistic learners.
int print_robustness(const EvaluateArgs& args, const std::shared_ptr<const CompileModel>& model, std::uint64_t seed) {
  if (args.task != TaskKind::writing) throw InputError("--robustness", "only for --task writing");
  const std::shared_ptr<const SkillExtractor> extractor = evaluation_extractor(args, model);
  std::fprintf(stderr, "evaluate-skills: %d classic words (seed %llu) by realistic learners...\n", args.count,
               static_cast<unsigned long long>(seed));
  const auto t0 = std::chrono::steady_clock::now();
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  const std::vector<std::string> words = writing::classic_words(args.count, seed);
  const std::vector<WritingRobustnessRow> rows =
      measure_writing_robustness(*extractor, glyphs, words, seed, writing_robustness_conditions());
  std::printf("%s, %d words of seed %llu per condition (learner seeds Rng(%llu).fork(word)):\n\n%s",
              args.time_heuristic ? "time heuristic" : args.model.c_str(), args.count,
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed),
              robustness_table(rows).c_str());
  const std::vector<CrossHandConsistency> cross =
      cross_hand_consistency(*extractor, glyphs, words, seed, {training_drawers(), unseen_drawers()});
  std::printf(
      "\ncross-hand consistency (no true boundaries; writing_cross_hand.hpp): drawers 1-10 %.3f (kappa %.3f), "
      "unseen drawers 11-15 %.3f (kappa %.3f)\n",
      cross[0].share(), cross[0].kappa(), cross[1].share(), cross[1].kappa());
  std::fprintf(stderr, "evaluate-skills: %.1f s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}

// Planted weaknesses under realistic input (writing): Alg. 2 on the app's pre-test written by planted learners.
int print_planted_weaknesses(const EvaluateArgs& args, const std::shared_ptr<const CompileModel>& model,
                             std::uint64_t seed) {
  if (args.task != TaskKind::writing) throw InputError("--planted-weaknesses", "only for --task writing");
  const std::unique_ptr<WritingKit> kit_owner = evaluation_writing_kit(args, model);
  const WritingKit& kit = *kit_owner;
  std::fprintf(stderr, "evaluate-skills: %d planted learners per letter and %d noise-only learners (seed %llu)...\n",
               args.learners, args.learners, static_cast<unsigned long long>(seed));
  const auto t0 = std::chrono::steady_clock::now();
  const PlantedWeaknessReport report =
      measure_planted_weaknesses(kit, ClassicDrawerGlyphs::load(), args.learners, seed, args.expertise, args.own_hands);
  std::printf("%s, %d learners per letter, seed %llu, %s expertise:\n%s",
              args.time_heuristic ? "time heuristic" : args.model.c_str(), args.learners,
              static_cast<unsigned long long>(seed), expertise_mode_name(args.expertise).c_str(),
              planted_weakness_table(report).c_str());
  std::fprintf(stderr, "evaluate-skills: %.1f s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}

// Quality-aware expertise's noise floor (writing): the segment scores of the planted table's noise-only learners.
int print_noise_floor(const EvaluateArgs& args, const std::shared_ptr<const CompileModel>& model, std::uint64_t seed) {
  if (args.task != TaskKind::writing)
    throw InputError("--noise-floor",
                     "only for --task writing here (parking: "
                     "evaluate-diagnosis --noise-floor)");
  if (args.record && args.time_heuristic) throw InputError("--record", "needs a model file (--model)");
  const std::unique_ptr<WritingKit> kit_owner = evaluation_writing_kit(args, model);
  const WritingKit& kit = *kit_owner;
  std::fprintf(stderr, "evaluate-skills: %d noise-only learners (seed %llu)...\n", args.learners,
               static_cast<unsigned long long>(seed));
  const NoiseFloorCalibration calibration = calibrate_writing_noise_floor(kit, args.learners, seed);
  std::printf("%s, seed %llu: %s", args.time_heuristic ? "time heuristic" : args.model.c_str(),
              static_cast<unsigned long long>(seed),
              noise_floor_report(calibration, kit.execution_noise_floor()).c_str());
  if (args.record) {
    record_noise_floor(args.model, calibration, seed);
    std::printf("recorded this calibration's floors (the 1 %% figures above) in %s\n",
                model_sidecar_path(args.model).string().c_str());
  }
  return 0;
}

int run(const EvaluateArgs& args) {
  if (args.model.empty() && !args.time_heuristic)
    throw InputError("evaluate-skills", "give a model (--model FILE) or --time-heuristic");
  std::shared_ptr<const CompileModel> model;
  // The time heuristic has no training seed; 1 is what a model trained with the default --seed 0 is scored on.
  std::uint64_t seed = args.seed ? *args.seed : 1;
  if (!args.time_heuristic) {
    model = load_model(args);
    // Held-out data: the training data was generated from the model's own seed.
    seed = args.seed ? *args.seed : model->config().seed + 1;
    if (seed == model->config().seed)
      throw InputError("--seed", std::to_string(seed) + " is the seed the model was trained with; pick another");
  }
  if (args.robustness) return print_robustness(args, model, seed);
  if (args.planted) return print_planted_weaknesses(args, model, seed);
  if (args.noise_floor) return print_noise_floor(args, model, seed);
  std::fprintf(stderr, "evaluate-skills: generating %d %s demonstrations (seed %llu)...\n", args.count,
               std::string(to_string(args.task)).c_str(), static_cast<unsigned long long>(seed));
  const SkillDataSet data = generate_task_demos(args.task, args.count, seed);
  const std::vector<StepSequence> steps = data.steps();
  const TimeHeuristicExtractor heuristic(CompileConfig::defaults_for(args.task).num_segments);
  const auto [segmentations, seconds] =
      timed([&] { return model ? model->segment(steps) : heuristic.extract_all(steps); });

  Json report = skill_quality_report(data, segmentations);
  if (model) {
    report["model"] = args.model;
    report["action_reconstruction_error"] = model->action_reconstruction_error(steps);
  } else {
    report["extractor"] = "time-heuristic (" + std::to_string(heuristic.num_skills()) + " equal segments)";
  }
  report["seed"] = seed;
  report["segmentation_seconds"] = seconds;
  if (args.details) report["demos"] = demo_details(data, segmentations);
  if (args.realistic_drivers) {
    if (args.task != TaskKind::parking) throw InputError("--realistic-drivers", "only for --task parking");
    std::fprintf(stderr, "evaluate-skills: skills of realistic drivers' copies vs the clean drives:\n");
    const std::vector<ParkingTrial> drives = held_out_drives(args.count, seed);
    // Read as the parking kit reads a learner's drive (parking_drive_reading.hpp).
    const std::shared_ptr<const SkillExtractor> extractor =
        parking_drive_reader(evaluation_extractor(args, model), shipped_pool_piece_length(), args.reading);
    report["realistic_drivers"] = realistic_driver_rows(*extractor, drives, seed);
    report["keyed_actions_on_clean_motion"] = keyed_action_row(*extractor, drives);
    report["expert_actions_at_limits"] = limits_row(drives);
  }
  std::printf("%s\n", report.dump(1).c_str());
  return 0;
}

CommandRunner setup_evaluate_skills(CLI::App& sub) {
  auto args = std::make_shared<EvaluateArgs>();
  add_task_option(sub, args->task)->required();
  auto* model = sub.add_option("--model", args->model, "CompILE model file");
  auto* heuristic = sub.add_flag("--time-heuristic", args->time_heuristic,
                                 "Score the paper's Time Heuristic baseline (K equal segments, K of the task's "
                                 "defaults) instead of a model: the yardstick for a model's figures");
  model->excludes(heuristic);
  heuristic->excludes(model);
  sub.add_option("--count", args->count, "Demonstrations to generate")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  sub.add_option("--seed", args->seed,
                 "Seed of the generated demonstrations (default: the model's seed + 1; 1 with --time-heuristic)");
  auto* realistic =
      sub.add_flag("--realistic-drivers", args->realistic_drivers,
                   "Parking: also drive each demonstration as novices on a gamepad, mouse joystick or keyboard would "
                   "(noise, delay, 15 Hz input) and report how often their skills agree with the clean drive's");
  sub.add_flag("--read-whole-drives", args->reading.whole_drive,
               "Research, with --realistic-drivers: read each copy whole, standing still at its ends included, as "
               "before 2026-12-05 (docs/skills.md, \"A standing start\")")
      ->needs(realistic);
  sub.add_flag("--read-in-one-piece", args->reading.one_piece,
               "Research, with --realistic-drivers: read a long copy in one piece, as before 2026-12-06 "
               "(docs/skills.md, \"A learner who keeps driving\")")
      ->needs(realistic);
  sub.add_flag("--details", args->details,
               "Also list every demonstration: its true boundaries and the predicted [skill, start, end] segments");
  sub.add_flag("--robustness", args->robustness,
               "Writing: print the robustness table instead (boundary F1 and letter->skill agreement on --count words "
               "written by realistic learners: mouse sampling, wobble, unseen drawers; docs/skills.md \"Robustness\")");
  auto* planted = sub.add_flag(
      "--planted-weaknesses", args->planted,
      "Writing: print the planted-weakness table instead (Alg. 2 on the app's pre-test written by learners who "
      "write one letter badly and the rest with realistic noise; docs/skills.md \"Robustness\")");
  auto* noise_floor = sub.add_flag(
      "--noise-floor", args->noise_floor,
      "Writing: print the noise-only learners' segment scores instead, and the noise floor they give quality-aware "
      "expertise (docs/skills.md \"A fourth change: a noise floor\")");
  sub.add_option("--learners", args->learners,
                 "Learners per letter (and noise-only learners) for --planted-weaknesses, learners for --noise-floor")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  auto* expertise =
      sub.add_option("--expertise", args->expertise,
                     "With --planted-weaknesses: alg2 (the paper's Alg. 2, research mode) or "
                     "quality-aware (Alg. 2 plus how well each skill was done; writing learners' default)")
          ->default_str("alg2")
          ->transform(CLI::CheckedTransformer(expertise_modes_by_name()));
  expertise->needs(planted);
  sub.add_flag("--own-hands", args->own_hands,
               "With --planted-weaknesses: every learner writes all its letters in the shapes of one unseen drawer "
               "(11-15), not the paper's (docs/skills.md \"Learners in their own hand\")")
      ->needs(planted);
  planted->excludes(sub.get_option("--robustness"));
  noise_floor->excludes(planted)->excludes(sub.get_option("--robustness"));
  auto* record = sub.add_flag("--record", args->record,
                              "With --noise-floor: record the floor in the model's JSON sidecar, where the app "
                              "reads it (train-skills does this for every writing model it trains)")
                     ->needs(noise_floor);
  sub.add_option("--readout-phases", args->readout_phases,
                 "Read the model at this many phases of its resampling instead of the file's (1 = one reading, "
                 "as every model before 2026-12-05; docs/skills.md \"Reading at three phases\")")
      ->check(CLI::Range(1, 16))
      ->excludes(heuristic)
      ->excludes(record);
  return [args] { return run(*args); };
}

const CommandRegistration kEvaluateSkillsCommandRegistration{
    {"evaluate-skills", "Measure a CompILE model's (or the time heuristic's) segmentation quality on fresh expert data",
     "skillcoach evaluate-skills --task writing --model assets/models/writing.pt --count 200", setup_evaluate_skills}};

}  // namespace
}  // namespace sc::cli
