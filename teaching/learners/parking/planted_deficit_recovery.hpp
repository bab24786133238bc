#pragma once
// Planted-weakness recovery under realistic input: does the diagnosis find a deficit planted in noisy,
// delayed, device-quantised drivers (realistic_driver.hpp), and leave noise-only drivers alone?
//
// Spec. Learner i of a run (seed S) drives with device i mod 3 (gamepad, mouse joystick, keyboard) and a
// novice profile drawn from Rng(S).fork(i) (sample_novice_profile), plus the deficit under test. Its
// pre-test is the kit's `pretest` expert drives, each driven as the profile drives it (Rng(S).fork(i)
// .fork(1 + k) for drive k), then diagnosed with diagnose_trials in the given mode.
//  * A deficit's skills are the used skills it spoils, as their words tell the learner: the "reversing"
//    skills (never reversing), the "braking" skills (late braking) - motion_reverses / motion_brakes - and
//    the skills steering beyond half lock on most (>= 50 %) of their expert steps (weak steering).
//  * Recovered: the first K targets are all deficit skills, K = min(kTopTargets, N_target, deficit skills
//    the pre-test's expert drives use). A pre-test without any deficit skill cannot show the deficit and counts as
//    missed.
//  * Noise-only learners: quiet when no skill's expertise per pre-test trial (E_m / trials) lies below the
//    mode's threshold (kQuietExpertise*).
#include <cstdint>
#include <vector>

#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/learners/parking/realistic_driver.hpp"
#include "teaching/tasks/parking_kit.hpp"

namespace sc {

// Expertise per pre-test trial below which a skill counts as weak, per mode: set by hand before the first
// run (seed 1) and not changed since; the table is reported at seed 2 (docs/skills.md, "Robustness on
// realistic learners").
inline constexpr int kTopTargets = 3;  // the "top 3 targets" (parking's N_target is larger)

inline constexpr double kQuietExpertiseAlg2 = -0.05;
inline constexpr double kQuietExpertiseQualityAware = -0.1;
double quiet_expertise_threshold(ExpertiseMode mode);

// Skills (ids) the deficit spoils, from the kit's skill motions; empty for PlantedDeficit::None.
std::vector<int> deficit_skills(PlantedDeficit deficit, const std::vector<ParkingSkillMotion>& motions);

struct LearnerOutcome {
  std::vector<int> targets;
  std::vector<double> target_per_trial;  // each target's E_m / trials (0: no penalty, the ranking's tie-break)
  double weakest_per_trial = 0.0;        // min over ranked skills of E_m / trials (0 when none ranked)
  int deficit_skills_seen = 0;           // deficit skills among the ranked (pre-test) skills
  bool recovered = false;                // see the spec (false for PlantedDeficit::None)
  bool quiet = false;                    // weakest_per_trial >= the mode's threshold
};

// Who the learners of a run are: the pre-test they take (indices into the kit's pool), the seed S of their draws,
// and how long each stands still before its first input and after its last (RealisticDriverProfile::start_wait_s,
// end_wait_s; drawn from nothing, so every other draw stays the same). The tables' learners stand for neither.
struct PlantedLearners {
  std::vector<int> pretest;
  std::uint64_t seed = 0;
  double start_wait_s = 0.0;
  double end_wait_s = 0.0;
  // Each drives on after the expert's plan until the kit's time limit for the drive (keeps_trying_until_s).
  bool keeps_trying = false;
  // The keyboard learners hold Shift to steer gently (shift_for_gentle_steering; draws nothing).
  bool keyboard_shift = false;
};

// Learner `learner`'s pre-test trials (documents), as the spec above drives them.
std::vector<Json> planted_learner_trials(const ParkingKit& kit, const PlantedLearners& run, PlantedDeficit deficit,
                                         int learner);

// One learner's diagnosis.
LearnerOutcome diagnose_planted_learner(const ParkingKit& kit, const PlantedLearners& run, PlantedDeficit deficit,
                                        ExpertiseMode mode, int learner);

struct RecoveryRow {
  PlantedDeficit deficit = PlantedDeficit::None;
  ExpertiseMode mode = ExpertiseMode::Alg2;
  int learners = 0;
  int recovered = 0;  // planted deficits: the first K (<= kTopTargets) targets all deficit skills
  int top1 = 0;       // the first target is a deficit skill
  int quiet = 0;      // no skill below the threshold (the share that should be high for None only)
};

// Learners 0..learners-1 for every deficit (None, NeverReversing, WeakSteering, LateBraking) x mode.
std::vector<RecoveryRow> planted_deficit_table(const ParkingKit& kit, const PlantedLearners& run, int learners);

// Per skill id, the share of noise-only learners 0..learners-1 whom Alg. 2 charges with it (E_m < 0). A skill that
// noise alone makes learners miss is weak evidence of a deficit (docs/skills.md, *A lead, not shipped*).
std::vector<double> noise_only_charge_rates(const ParkingKit& kit, const PlantedLearners& run, int learners);

}  // namespace sc
