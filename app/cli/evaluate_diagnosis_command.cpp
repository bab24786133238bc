// skillcoach evaluate-diagnosis --task parking [--model FILE] [--learners N] [--seed S]: planted-weakness
// recovery under realistic input (teaching/learners/parking/planted_deficit_recovery.hpp). Noisy, delayed
// drivers on each device with a planted deficit (never reversing, weak steering, late braking) or none take
// the kit's pre-test; the table says how often the deficit's skills fill the top targets and how often a
// learner gets no skill below the expertise threshold, for Alg. 2 and for quality-aware expertise.
// --charge-rates prints, per skill, how many noise-only learners Alg. 2 charges with it;
// --noise-floor prints the learners' segment scores instead (the noise floor the noise-only learners give
// quality-aware expertise, and how much of each deficit's segments score above it); --apply-noise-floor F
// measures the table with that floor (ParkingKitOptions::execution_noise_floor; the shipped kit uses none).
// --start-wait S / --end-wait S make every learner stand still S seconds before / after driving, --keeps-trying
// makes it drive on until the time limit, --keyboard-shift makes the keyboard learners hold Shift to steer gently;
// --read-whole-drives and --read-in-one-piece read drives as the kit did before 2026-12-05 / 2026-12-06
// (ParkingKitOptions::reading).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "teaching/learners/parking/planted_deficit_recovery.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/piecewise_extractor.hpp"
#include "teaching/tasks/execution_noise_floor.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc::cli {
namespace {

struct EvaluateDiagnosisArgs {
  TaskKind task = TaskKind::parking;
  std::string model;
  int learners = 20;
  int pretest = 5;  // the app's pre-test (SessionSettings::pretest_count)
  unsigned long long seed = 2;
  bool details = false;
  bool noise_floor = false;
  bool charge_rates = false;
  std::optional<double> apply_noise_floor;
  double start_wait = 0.0;
  double end_wait = 0.0;
  bool keeps_trying = false;
  bool keyboard_shift = false;
  ParkingDriveReading reading;
};

// Each deficit's learners' segment scores against the noise-only learners' floor.
void print_noise_floor(const ParkingKit& kit, const PlantedLearners& run, const EvaluateDiagnosisArgs& args) {
  std::optional<double> floor;
  for (PlantedDeficit d : {PlantedDeficit::None, PlantedDeficit::NeverReversing, PlantedDeficit::WeakSteering,
                           PlantedDeficit::LateBraking}) {
    std::vector<std::vector<Json>> learners;
    for (int i = 0; i < args.learners; ++i) learners.push_back(planted_learner_trials(kit, run, d, i));
    const NoiseFloorCalibration c = calibrate_noise_floor(kit, learners);
    if (!floor) {
      floor = c.floor();
      std::printf("%s", noise_floor_report(c, kit.execution_noise_floor()).c_str());
      continue;
    }
    const auto above = std::count_if(c.scores.begin(), c.scores.end(), [&](double q) { return q >= *floor; });
    std::printf("%s: %zu segments, 1 %% %.3f, 5 %% %.3f, median %.3f; %.0f %% score at or above the noise floor\n",
                deficit_name(d).c_str(), c.scores.size(), c.percentile(1.0), c.percentile(5.0), c.percentile(50.0),
                100.0 * static_cast<double>(above) / static_cast<double>(c.scores.size()));
  }
}

// Every learner's first targets (deficit skills starred) with their expertise per trial (0.000: no penalty, placed
// by the ranking's tie-break), for each deficit and mode, to see what goes wrong.
void print_details(const ParkingKit& kit, const PlantedLearners& run, const EvaluateDiagnosisArgs& args) {
  for (PlantedDeficit d : {PlantedDeficit::None, PlantedDeficit::NeverReversing, PlantedDeficit::WeakSteering,
                           PlantedDeficit::LateBraking})
    for (ExpertiseMode mode : {ExpertiseMode::Alg2, ExpertiseMode::QualityAware}) {
      const std::vector<int> spoiled = deficit_skills(d, kit.skill_motions());
      std::printf("%s, %s:\n", deficit_name(d).c_str(), mode == ExpertiseMode::Alg2 ? "Alg. 2" : "quality-aware");
      for (int i = 0; i < args.learners; ++i) {
        const LearnerOutcome o = diagnose_planted_learner(kit, run, d, mode, i);
        std::printf("  learner %2d (%s): weakest E/trial %7.3f, targets", i,
                    device_name(static_cast<DriveDevice>(i % 3)).c_str(), o.weakest_per_trial);
        for (std::size_t k = 0; k < o.targets.size() && k < 5; ++k) {
          const bool hit = std::find(spoiled.begin(), spoiled.end(), o.targets[k]) != spoiled.end();
          std::printf(" %d%s (%.3f)", o.targets[k], hit ? "*" : "", o.target_per_trial[k]);
        }
        std::printf("\n");
      }
    }
}

const char* mode_name(ExpertiseMode mode) { return mode == ExpertiseMode::Alg2 ? "Alg. 2" : "quality-aware"; }

std::string skill_list(const std::vector<int>& skills) {
  std::string out;
  for (int m : skills) out += (out.empty() ? "" : " ") + std::to_string(m);
  return out.empty() ? "-" : out;
}

int run(const EvaluateDiagnosisArgs& args) {
  if (args.task != TaskKind::parking) throw InputError("evaluate-diagnosis", "only --task parking is measured here");
  const std::unique_ptr<TaskKit> base =
      make_parking_kit(args.model, GoalRegion::WholeLot, args.apply_noise_floor, args.reading);
  const auto* kit = dynamic_cast<const ParkingKit*>(base.get());
  if (!kit) throw InputError("evaluate-diagnosis", "the parking kit did not load");
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  const PlantedLearners run{
      .pretest = select_diverse_scenarios(demo_skills(kit->expert_pool()), args.pretest).scenarios(),
      .seed = args.seed,
      .start_wait_s = args.start_wait,
      .end_wait_s = args.end_wait,
      .keeps_trying = args.keeps_trying,
      .keyboard_shift = args.keyboard_shift};
  std::printf("parking, %s, %d learners per row, seed %llu, pre-test of %zu pool drives",
              kit->extractor().name().c_str(), args.learners, args.seed, run.pretest.size());
  if (args.start_wait > 0.0) std::printf(", each learner standing %.1f s before driving", args.start_wait);
  if (args.end_wait > 0.0) std::printf(", standing %.1f s after driving", args.end_wait);
  if (args.keeps_trying) std::printf(", driving on until the time limit");
  if (args.keyboard_shift) std::printf(", keyboard learners steering gently with Shift");
  if (args.reading.whole_drive) std::printf(", drives read whole (standing still included)");
  if (args.reading.one_piece) std::printf(", long drives read in one piece");
  if (!args.reading.whole_drive && !args.reading.one_piece)
    std::printf(", drives of %d steps or more read in pieces of about %d", shortest_split_length(kit->piece_length()),
                kit->piece_length());
  std::printf("\n");
  for (PlantedDeficit d : {PlantedDeficit::NeverReversing, PlantedDeficit::WeakSteering, PlantedDeficit::LateBraking})
    std::printf("  %s skills: %s\n", deficit_name(d).c_str(),
                skill_list(deficit_skills(d, kit->skill_motions())).c_str());
  std::printf("quiet thresholds (expertise per pre-test trial): Alg. 2 %.3f, quality-aware %.3f\n\n",
              kQuietExpertiseAlg2, kQuietExpertiseQualityAware);
  if (args.noise_floor) {
    print_noise_floor(*kit, run, args);
    return 0;
  }
  if (args.charge_rates) {
    const std::vector<double> rates = noise_only_charge_rates(*kit, run, args.learners);
    std::printf("noise-only learners charged with each skill (Alg. 2, E_m < 0), of %d:\n", args.learners);
    for (std::size_t m = 0; m < rates.size(); ++m)
      std::printf("  skill %2zu: %4ld  %s\n", m, std::lround(rates[m] * args.learners),
                  kit->describe_skill(static_cast<int>(m)).c_str());
    return 0;
  }
  if (args.details) {
    for (int m = 0; m < kit->extractor().num_skills(); ++m) {
      const ParkingSkillMotion& s = kit->skill_motions()[static_cast<std::size_t>(m)];
      std::printf(
          "  skill %2d: %-70s %4d steps, speed %5.2f m/s, u0 %5.2f, reversing %3.0f %%, sharp %3.0f %%, braking %3.0f "
          "%%\n",
          m, kit->describe_skill(m).c_str(), s.steps, s.mean_speed, s.mean_acceleration, 100 * s.reverse_fraction,
          100 * s.sharp_fraction, 100 * s.braking_fraction);
    }
    print_details(*kit, run, args);
    return 0;
  }
  std::printf(
      "| planted deficit | expertise | deficit skills fill the top targets | first target a deficit skill | no skill "
      "below the threshold |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const RecoveryRow& r : planted_deficit_table(*kit, run, args.learners)) {
    const bool planted = r.deficit != PlantedDeficit::None;
    auto share = [&](int n) { return std::to_string(n) + " / " + std::to_string(r.learners); };
    std::printf("| %s | %s | %s | %s | %s |\n", deficit_name(r.deficit).c_str(), mode_name(r.mode),
                planted ? share(r.recovered).c_str() : "-", planted ? share(r.top1).c_str() : "-",
                share(r.quiet).c_str());
    std::fflush(stdout);
  }
  return 0;
}

CommandRunner setup_evaluate_diagnosis(CLI::App& sub) {
  auto args = std::make_shared<EvaluateDiagnosisArgs>();
  add_task_option(sub, args->task, "parking (writing: not measured by this command)")->required();
  sub.add_option("--model", args->model, "CompILE model file (default: assets/models/parking.pt)");
  sub.add_option("--learners", args->learners, "Learners per deficit and mode")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  sub.add_option("--pretest", args->pretest, "Pre-test drives (diverse pool scenarios)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  sub.add_option("--seed", args->seed, "Seed of the learners (1 was used to choose the thresholds)")
      ->capture_default_str();
  auto* details =
      sub.add_flag("--details", args->details,
                   "Instead of the table: every skill's words and every learner's first targets (* = a deficit skill)");
  sub.add_flag("--charge-rates", args->charge_rates,
               "Instead of the table: how many noise-only learners Alg. 2 charges with each skill (a skill noise alone "
               "makes learners miss)");
  sub.add_flag("--noise-floor", args->noise_floor,
               "Instead of the table: the learners' segment scores, the noise floor the noise-only learners give "
               "quality-aware expertise and how much of each deficit's segments score above it")
      ->excludes(details);
  sub.add_option("--apply-noise-floor", args->apply_noise_floor,
                 "Measure with this noise floor in quality-aware expertise (<= 0; the shipped parking kit uses none)")
      ->check(CLI::Range(-10.0, 0.0));
  sub.add_option("--start-wait", args->start_wait,
                 "Every learner stands still this many seconds before its first input, as after the trainer's "
                 "countdown (0: after its reaction delay only, the tables' learners)")
      ->check(CLI::Range(0.0, 10.0));
  sub.add_option("--end-wait", args->end_wait,
                 "Every learner brakes to a standstill after its last input and stands this many seconds, as one who "
                 "has given up on the spot does until the trainer's time limit")
      ->check(CLI::Range(0.0, 20.0));
  sub.add_flag("--keeps-trying", args->keeps_trying,
               "Every learner drives on after the expert's plan, towards where the expert's drive ended, until the "
               "trainer's time limit, as one who has not parked does (--end-wait comes first)");
  sub.add_flag("--keyboard-shift", args->keyboard_shift,
               "The keyboard learners hold Shift where the expert steers nearer half lock than full lock or straight "
               "(the tables' keyboard learners use the arrows alone)");
  sub.add_flag("--read-whole-drives", args->reading.whole_drive,
               "Research: read each drive whole, standing still at its ends included, as before 2026-12-05 "
               "(the kit reads from the first to the last moving step; docs/skills.md, \"A standing start\")");
  sub.add_flag("--read-in-one-piece", args->reading.one_piece,
               "Research: read a long drive in one piece, as before 2026-12-06 (the kit reads a drive much longer "
               "than the pool's longest in pieces about that long; docs/skills.md, \"A learner who keeps driving\")");
  return [args] { return run(*args); };
}

const CommandRegistration kEvaluateDiagnosisCommandRegistration{
    {"evaluate-diagnosis",
     "Planted-weakness recovery of the diagnosis on realistic (noisy, delayed, per-device) learners",
     "skillcoach evaluate-diagnosis --task parking --learners 20 --seed 2", setup_evaluate_diagnosis}};

}  // namespace
}  // namespace sc::cli
