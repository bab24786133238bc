// Planted deficits in realistic drivers, diagnosed with the shipped parking model (the full table:
// `skillcoach evaluate-diagnosis --task parking`, docs/skills.md). A handful of learners keeps this cheap.
#include "teaching/learners/parking/planted_deficit_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/tasks/expert_demos.hpp"

namespace sc {
namespace {

TEST(PlantedDeficitRecovery, DeficitSkillsAreTheSkillsWhoseWordsNameWhatTheDeficitSpoils) {
  std::vector<ParkingSkillMotion> motions(4);
  for (auto& m : motions) m.steps = 10;
  motions[0].mean_speed = -3.0;  // "reversing ..."
  motions[1].mean_speed = 2.0;
  motions[1].sharp_fraction = 0.6;
  motions[2].mean_speed = 4.0;  // "driving forward ..., braking"
  motions[2].mean_acceleration = -0.5;
  motions[3].steps = 0;  // unused
  motions[3].mean_speed = -3.0;
  EXPECT_EQ(deficit_skills(PlantedDeficit::NeverReversing, motions), (std::vector<int>{0}));
  EXPECT_EQ(deficit_skills(PlantedDeficit::WeakSteering, motions), (std::vector<int>{1}));
  EXPECT_EQ(deficit_skills(PlantedDeficit::LateBraking, motions), (std::vector<int>{2}));
  EXPECT_TRUE(deficit_skills(PlantedDeficit::None, motions).empty());
}

const std::filesystem::path kShipped = asset_dir() / "models" / "parking.pt";

struct Setup {
  std::unique_ptr<ParkingKit> kit;
  std::vector<int> pretest;
};

const Setup& setup() {
  static const Setup s = [] {
    Setup out;
    auto extractor = std::make_shared<CompileExtractor>(CompileExtractor::load(kShipped, "parking"));
    out.kit =
        std::make_unique<ParkingKit>(extractor, "", ParkingKitOptions{default_parking_pool_file(), {}, std::nullopt});
    out.pretest = select_diverse_scenarios(demo_skills(out.kit->expert_pool()), 5).scenarios();
    return out;
  }();
  return s;
}

// Seed 3: neither the seed the thresholds were chosen on (1) nor the table's (2).
constexpr std::uint64_t kSeed = 3;
constexpr int kLearners = 6;

// What holds at every seed measured (docs/skills.md): the first target of a noisy learner who never
// reverses is a reversing skill, and such learners look weaker than noise-only ones. (Filling all of the
// top 3 targets and keeping every noise-only learner above the threshold do not hold; see the docs.)
TEST(PlantedDeficitRecovery, NeverReversingNoisyLearnersAreFirstDrilledOnReversingAndWeakerThanNoiseOnlyOnes) {
  ASSERT_TRUE(std::filesystem::exists(kShipped)) << kShipped.string();
  const PlantedLearners run{setup().pretest, kSeed};
  for (ExpertiseMode mode : {ExpertiseMode::Alg2, ExpertiseMode::QualityAware}) {
    const std::vector<int> reversing = deficit_skills(PlantedDeficit::NeverReversing, setup().kit->skill_motions());
    int first_reverses = 0;
    double planted = 0.0, noise_only = 0.0;
    for (int i = 0; i < kLearners; ++i) {
      const LearnerOutcome o = diagnose_planted_learner(*setup().kit, run, PlantedDeficit::NeverReversing, mode, i);
      ASSERT_FALSE(o.targets.empty());
      // Each target's expertise, weakest first: the first is the learner's weakest skill.
      ASSERT_EQ(o.target_per_trial.size(), o.targets.size());
      EXPECT_TRUE(std::is_sorted(o.target_per_trial.begin(), o.target_per_trial.end()));
      EXPECT_DOUBLE_EQ(o.target_per_trial.front(), o.weakest_per_trial);
      first_reverses += std::find(reversing.begin(), reversing.end(), o.targets.front()) != reversing.end();
      planted += o.weakest_per_trial;
      noise_only += diagnose_planted_learner(*setup().kit, run, PlantedDeficit::None, mode, i).weakest_per_trial;
    }
    EXPECT_GE(first_reverses, kLearners - 1) << "mode " << static_cast<int>(mode);
    EXPECT_LT(planted, noise_only) << "mode " << static_cast<int>(mode);
  }
}

// A learner in the trainer stands still after the countdown before driving. Read from the first moving step
// (the kit), a second of that leaves noise-only learners as quiet as without it; read whole, it gave many of them
// a confident target (docs/skills.md, "A standing start"). Seed 14: no table's.
TEST(PlantedDeficitRecovery, NoiseOnlyLearnersWhoStandASecondFirstStayQuiet) {
  ASSERT_TRUE(std::filesystem::exists(kShipped)) << kShipped.string();
  auto extractor = std::make_shared<CompileExtractor>(CompileExtractor::load(kShipped, "parking"));
  const ParkingKit whole(extractor, "",
                         ParkingKitOptions{default_parking_pool_file(), {}, std::nullopt, {.whole_drive = true}});
  constexpr int kQuietLearners = 20;
  const PlantedLearners on_time{setup().pretest, 14}, standing{setup().pretest, 14, 1.0};
  auto quiet = [&](const ParkingKit& kit, const PlantedLearners& run) {
    int n = 0;
    for (int i = 0; i < kQuietLearners; ++i)
      n += diagnose_planted_learner(kit, run, PlantedDeficit::None, ExpertiseMode::Alg2, i).quiet;
    return n;
  };
  const int shipped_on_time = quiet(*setup().kit, on_time), shipped_standing = quiet(*setup().kit, standing);
  const int whole_standing = quiet(whole, standing);
  EXPECT_GE(shipped_standing, shipped_on_time - 1) << shipped_on_time << " on time";
  EXPECT_LE(whole_standing, shipped_standing - 3) << shipped_standing << " read from the first moving step";
}

// ... and one who gives up on the spot and stands until the time limit: weak steering is still found as often.
TEST(PlantedDeficitRecovery, WeakSteeringLearnersWhoStandAtTheEndAreFoundAsOften) {
  ASSERT_TRUE(std::filesystem::exists(kShipped)) << kShipped.string();
  auto extractor = std::make_shared<CompileExtractor>(CompileExtractor::load(kShipped, "parking"));
  const ParkingKit whole(extractor, "",
                         ParkingKitOptions{default_parking_pool_file(), {}, std::nullopt, {.whole_drive = true}});
  const PlantedLearners on_time{setup().pretest, 14}, standing{setup().pretest, 14, 0.0, 5.0};
  auto found = [&](const ParkingKit& kit, const PlantedLearners& run) {
    int n = 0;
    for (int i = 0; i < 20; ++i)
      n += diagnose_planted_learner(kit, run, PlantedDeficit::WeakSteering, ExpertiseMode::Alg2, i).recovered;
    return n;
  };
  const int shipped_on_time = found(*setup().kit, on_time), shipped_standing = found(*setup().kit, standing);
  EXPECT_GE(shipped_standing, shipped_on_time - 1) << shipped_on_time << " on time";
  EXPECT_LE(found(whole, standing), shipped_standing - 2) << shipped_standing << " read from first to last move";
}

// A learner who has not parked keeps driving until the time limit, three to four times as long as the expert. Read
// in pieces about as long as the pool's drives (the kit), weak steering is found more often than read in one piece,
// and noise-only learners stay as quiet (docs/skills.md, "A learner who keeps driving"). Seeds 14 and 16: no table's.
TEST(PlantedDeficitRecovery, WeakSteeringLearnersWhoKeepTryingAreFoundMoreOftenReadInPieces) {
  ASSERT_TRUE(std::filesystem::exists(kShipped)) << kShipped.string();
  auto extractor = std::make_shared<CompileExtractor>(CompileExtractor::load(kShipped, "parking"));
  const ParkingKit one_piece(extractor, "",
                             ParkingKitOptions{default_parking_pool_file(), {}, std::nullopt, {.one_piece = true}});
  auto count = [&](const ParkingKit& kit, PlantedDeficit deficit) {
    int n = 0;
    for (std::uint64_t seed : {14, 16}) {
      const PlantedLearners trying{setup().pretest, seed, 0.0, 0.0, true};
      for (int i = 0; i < 20; ++i) {
        const LearnerOutcome o = diagnose_planted_learner(kit, trying, deficit, ExpertiseMode::Alg2, i);
        n += deficit == PlantedDeficit::None ? o.quiet : o.recovered;
      }
    }
    return n;
  };
  const int pieces_found = count(*setup().kit, PlantedDeficit::WeakSteering);
  EXPECT_GE(pieces_found, count(one_piece, PlantedDeficit::WeakSteering) + 3) << pieces_found << " in pieces";
  const int pieces_quiet = count(*setup().kit, PlantedDeficit::None);
  EXPECT_GE(pieces_quiet, count(one_piece, PlantedDeficit::None) - 1) << pieces_quiet << " in pieces";
}

// The charge rates count exactly the noise-only learners whose expertise in a skill is negative: every loud learner's
// weakest skill is counted, and a skill no expert drive uses never is.
TEST(PlantedDeficitRecovery, ChargeRatesCountTheNoiseOnlyLearnersChargedWithEachSkill) {
  const PlantedLearners run{setup().pretest, kSeed};
  const std::vector<double> rates = noise_only_charge_rates(*setup().kit, run, kLearners);
  ASSERT_EQ(rates.size(), static_cast<std::size_t>(setup().kit->extractor().num_skills()));
  std::vector<int> charged(rates.size(), 0);
  for (int i = 0; i < kLearners; ++i) {
    const LearnerOutcome o = diagnose_planted_learner(*setup().kit, run, PlantedDeficit::None, ExpertiseMode::Alg2, i);
    for (std::size_t t = 0; t < o.targets.size(); ++t)
      if (o.target_per_trial[t] < 0.0) ++charged[static_cast<std::size_t>(o.targets[t])];
  }
  for (std::size_t m = 0; m < rates.size(); ++m) {
    EXPECT_GE(rates[m] * kLearners + 1e-9, charged[m]) << m;  // targets are the first N_target of the ranking
    if (setup().kit->skill_motions()[m].steps == 0) {
      EXPECT_EQ(rates[m], 0.0) << m;
    }
  }
  EXPECT_GT(*std::max_element(rates.begin(), rates.end()), 0.0);
}

// A keyboard learner who holds Shift steers at half lock where the expert steers gently; the same learner (same
// draws) on the arrows alone never does, and the other devices' learners drive the same either way.
TEST(PlantedDeficitRecovery, KeyboardLearnersWhoHoldShiftSteerAtHalfLockAndNobodyElseChanges) {
  PlantedLearners arrows{setup().pretest, kSeed}, shift = arrows;
  shift.keyboard_shift = true;
  auto half_lock_actions = [](const std::vector<Json>& trials) {
    int n = 0;
    for (const Json& t : trials)
      for (const Json& a : t.at("actions")) n += std::abs(a.at(1).get<double>()) == 0.5;
    return n;
  };
  for (int learner : {0, 1, 2}) {  // gamepad, mouse, keyboard
    const std::vector<Json> with_shift = planted_learner_trials(*setup().kit, shift, PlantedDeficit::None, learner);
    const std::vector<Json> without = planted_learner_trials(*setup().kit, arrows, PlantedDeficit::None, learner);
    EXPECT_EQ(half_lock_actions(without), 0) << learner;
    if (learner == 2)
      EXPECT_GT(half_lock_actions(with_shift), 10);
    else
      EXPECT_EQ(with_shift, without) << learner;
  }
}

}  // namespace
}  // namespace sc
