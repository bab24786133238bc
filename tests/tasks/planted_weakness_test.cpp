// Planted-weakness checks: synthetic students with a known weakness must be diagnosed with it.
// The skills come from CompILE: the shipped model (assets/models/<task>.pt) when it exists, else a small
// CompILE trained here on the kit's own expert demos (the time heuristic's slices cannot know about
// reversing or characters, so it would make these checks meaningless).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/compile_trainer.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/diagnosis.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_planted_weakness.hpp"

namespace sc {
namespace {

// The shipped model, or a small CompILE trained on `demos` with the task's defaults scaled down.
std::shared_ptr<const SkillExtractor> compile_extractor(const std::string& task, const std::vector<StepSequence>& demos,
                                                        CompileConfig config) {
  const std::filesystem::path shipped = asset_dir() / "models" / (task + ".pt");
  if (std::filesystem::exists(shipped)) {
    std::printf("%s: using the shipped model %s\n", task.c_str(), shipped.string().c_str());
    return std::make_shared<CompileExtractor>(CompileExtractor::load(shipped, task));
  }
  CompileTrainer trainer(config);
  auto model = std::make_shared<const CompileModel>(trainer.train(demos, {}));
  std::printf("%s: trained a CompILE model here (%d iterations, %.1f s)\n", task.c_str(),
              trainer.summary().iterations_run, trainer.summary().seconds);
  return std::make_shared<CompileExtractor>(model);
}

void print_ranking(const TaskKit& kit, const ExpertiseEstimate& e) {
  for (int m : e.ranking)
    std::printf("  skill %2d  E = %8.4f  (%d uses)  %s\n", m, e.expertise[static_cast<std::size_t>(m)],
                e.occurrences[static_cast<std::size_t>(m)], kit.describe_skill(m).c_str());
}

// ---------------------------------------------------------------------------------------------- parking

// A student who never reverses: wherever the expert accelerates backwards, the student brakes to a stop
// instead (the deceleration that brings the speed to zero in one control step, never below), steering as
// the expert does; then the whole episode is re-simulated.
ParkingTrial never_reversing_student(const ParkingTrial& expert) {
  ParkingSim sim(expert.scenario);
  ParkingTrial student;
  student.scenario = expert.scenario;
  student.states.push_back(sim.observation());
  for (const ParkingAction& a : expert.actions) {
    if (sim.done()) break;
    ParkingAction u = clip_action(a);
    if (u[0] < 0.0) {
      const double speed = std::max(sim.vehicle().speed, 0.0);
      const double stop = -speed / (parking::kMaxAcceleration * parking::kControlHz);  // u0 that stops in 0.2 s
      u[0] = std::max(u[0], stop);
    }
    const ParkingStepResult r = sim.step(u);
    student.actions.push_back(u);
    student.states.push_back(sim.observation());
    student.rewards.push_back(r.reward);
  }
  student.success = sim.succeeded();
  student.source = "learner";
  return student;
}

struct ParkingSetup {
  std::vector<ParkingTrial> pool;
  std::unique_ptr<ParkingKit> kit;
  std::vector<int> pretest;
};

const ParkingSetup& parking() {
  static const ParkingSetup setup = [] {
    ParkingSetup s;
    s.pool = generate_parking_pool({60, 0});
    std::vector<StepSequence> demos;
    for (const ParkingTrial& t : s.pool) demos.push_back(parking_step_sequence(t));
    CompileConfig c = CompileConfig::parking_defaults();
    c.latent_size = 16;
    c.hidden = 64;
    c.batch_size = 60;
    c.iterations = 400;
    c.patience = 1000;
    c.seed = 1;
    s.kit = std::make_unique<ParkingKit>(compile_extractor("parking", demos, c), "", s.pool);
    s.pretest = select_diverse_scenarios(demo_skills(s.kit->expert_pool()), 10).scenarios();
    return s;
  }();
  return setup;
}

TEST(PlantedWeakness, ParkingStudentWhoNeverReversesIsWeakestAtReversing) {
  const ParkingSetup& s = parking();
  std::vector<Json> trials;
  int reversing_scenarios = 0;
  for (int i : s.pretest) {
    const ParkingTrial& expert = s.pool[static_cast<std::size_t>(i)];
    reversing_scenarios +=
        std::any_of(expert.actions.begin(), expert.actions.end(), [](const auto& a) { return a[0] < 0; });
    trials.push_back(parking_trial_to_json(never_reversing_student(expert)));
  }
  const Diagnosis d = diagnose_trials(*s.kit, trials, 0);
  std::printf("never-reversing student, %zu pre-test scenarios (%d with reverse acceleration):\n", trials.size(),
              reversing_scenarios);
  print_ranking(*s.kit, d.expertise);
  const auto& motions = s.kit->skill_motions();
  auto reversing = [&](int m) { return motions[static_cast<std::size_t>(m)].reverse_fraction >= 0.5; };
  int reversing_seen = 0, forward_seen = 0;
  double reversing_sum = 0.0, forward_sum = 0.0;
  for (int m : d.expertise.ranking) {
    const double e = d.expertise.expertise[static_cast<std::size_t>(m)];
    (reversing(m) ? reversing_sum : forward_sum) += e;
    ++(reversing(m) ? reversing_seen : forward_seen);
  }
  ASSERT_GT(reversing_seen, 0) << "the pre-test shows no reversing skill";
  // The issue: reversing skills must be among the lowest-expertise skills. Asserted as: the weakest skill
  // reverses; most of the N_target skills the drills go to reverse; reversing skills lost more expertise
  // on average than forward ones. (Not every reversing skill loses expertise: some are "reversing ...,
  // braking" skills whose segments are largely the braking this student still does, and CompILE gives
  // the student's braking those skills.)
  EXPECT_TRUE(reversing(d.expertise.ranking.front())) << "weakest skill " << d.expertise.ranking.front();
  const int targets = static_cast<int>(d.expertise.targets.size());
  const int reversing_targets =
      static_cast<int>(std::count_if(d.expertise.targets.begin(), d.expertise.targets.end(), reversing));
  EXPECT_GT(2 * reversing_targets, targets) << reversing_targets << " of " << targets << " targets reverse";
  if (forward_seen > 0) {
    EXPECT_LT(reversing_sum / reversing_seen, forward_sum / forward_seen) << "mean E: reversing vs forward skills";
  }
  // The drills target it.
  ASSERT_FALSE(d.drills.empty());
  EXPECT_TRUE(reversing(d.drills.front().plan.target_skill));
}

TEST(PlantedWeakness, ParkingStudentIdenticalToTheExpertIsNotPenalised) {
  const ParkingSetup& s = parking();
  std::vector<Json> trials;
  for (int i : s.pretest) trials.push_back(parking_trial_to_json(s.pool[static_cast<std::size_t>(i)]));
  const Diagnosis d = diagnose_trials(*s.kit, trials, 0);
  for (int m = 0; m < d.expertise.num_skills(); ++m) {
    EXPECT_FALSE(d.expertise.penalised(m)) << "skill " << m;
    EXPECT_EQ(d.expertise.expertise[static_cast<std::size_t>(m)], 0.0);
  }
}

// ---------------------------------------------------------------------------------------------- writing

constexpr char kDistorted = 'b';

// The student writes the expert's word, except that every `symbol` is a straight line from where the
// character starts to where it ends (same number of pen points, so the pace is unchanged).
writing::WritingTrial distorted_student(const writing::WordTrajectory& gold, char symbol) {
  std::vector<writing::TracePoint> points = gold.points();
  const int n = static_cast<int>(gold.word.size());
  for (int k = 0; k < n; ++k) {
    if (gold.word[static_cast<std::size_t>(k)] != symbol) continue;
    const int a = gold.character_starts[static_cast<std::size_t>(k)];
    const int b =
        k + 1 < n ? gold.character_starts[static_cast<std::size_t>(k + 1)] : static_cast<int>(gold.steps.size());
    const writing::TracePoint p0 = points[static_cast<std::size_t>(a)];
    const writing::TracePoint p1 = points[static_cast<std::size_t>(b)];
    for (int i = a + 1; i < b; ++i) {
      const double f = static_cast<double>(i - a) / (b - a);
      points[static_cast<std::size_t>(i)].x = p0.x + f * (p1.x - p0.x);
      points[static_cast<std::size_t>(i)].y = p0.y + f * (p1.y - p0.y);
    }
  }
  writing::WritingTrial trial;
  trial.scenario = {gold.word, gold.alphabet, {}};
  trial.points = std::move(points);
  trial.source = "learner";
  return trial;
}

// The writing check needs CompILE skills that follow the characters: the shipped model's (trained with the
// warm start, docs/skills.md). A CompILE trained here from random weights does not give them (measured: 30
// words, latent 12, hidden 32, 150 iterations -> only 2 of 12 skills used, none inside one character), and
// the full training takes ~6 minutes, so a checkout without the shipped model fails this check.
std::filesystem::path shipped_writing_model() { return asset_dir() / "models" / "writing.pt"; }

struct WritingSetup {
  std::unique_ptr<WritingKit> kit;
  std::vector<int> pretest;
};

// With the shipped model when it exists, else the time heuristic (enough for the identical student).
const WritingSetup& writing_setup() {
  static const WritingSetup setup = [] {
    WritingSetup s;
    if (std::filesystem::exists(shipped_writing_model()))
      s.kit = make_writing_kit(
          std::make_shared<CompileExtractor>(CompileExtractor::load(shipped_writing_model(), "writing")),
          shipped_writing_model());
    else
      s.kit = make_writing_kit(std::make_shared<TimeHeuristicExtractor>(kWritingTimeSlices), {});
    s.pretest = select_diverse_scenarios(demo_skills(s.kit->expert_pool()), 10).scenarios();
    return s;
  }();
  return setup;
}

TEST(PlantedWeakness, WritingStudentWithADistortedCharacterIsWeakestAtItsSkills) {
  ASSERT_TRUE(std::filesystem::exists(shipped_writing_model()))
      << shipped_writing_model().string() << " missing: train it with skillcoach train-skills --task writing --seed 0";
  const WritingSetup& s = writing_setup();
  std::vector<Json> trials;
  int with_symbol = 0;
  for (int i : s.pretest) {
    const writing::WordTrajectory& gold = s.kit->gold_words()[static_cast<std::size_t>(i)];
    with_symbol += gold.word.find(kDistorted) != std::string::npos;
    trials.push_back(writing::writing_trial_json(distorted_student(gold, kDistorted)));
  }
  const Diagnosis d = diagnose_trials(*s.kit, trials, 0);
  std::printf("student with a straight-line '%c', %zu pre-test words (%d contain it):\n", kDistorted, trials.size(),
              with_symbol);
  print_ranking(*s.kit, d.expertise);
  ASSERT_GT(with_symbol, 0);
  const auto& places = s.kit->skill_places();
  auto of_symbol = [&](int m) { return places[static_cast<std::size_t>(m)].share_of(kDistorted) >= 0.5; };
  for (int m : d.expertise.ranking)
    std::printf("  skill %2d: %.0f %% of its expert steps in '%c'\n", m,
                100 * places[static_cast<std::size_t>(m)].share_of(kDistorted), kDistorted);
  std::vector<int> seen;
  for (int m : d.expertise.ranking)
    if (of_symbol(m)) seen.push_back(m);
  ASSERT_FALSE(seen.empty()) << "no skill lies mostly in '" << kDistorted << "'";
  // The character's skills are the weakest: they come first in the ranking, all penalised.
  for (std::size_t r = 0; r < seen.size(); ++r) {
    EXPECT_TRUE(of_symbol(d.expertise.ranking[r])) << "rank " << r << ": skill " << d.expertise.ranking[r];
    EXPECT_TRUE(d.expertise.penalised(seen[r])) << "skill " << seen[r];
  }
}

TEST(PlantedWeakness, WritingStudentIdenticalToTheExpertIsNotPenalised) {
  const WritingSetup& s = writing_setup();
  std::vector<Json> trials;
  for (int i : s.pretest) trials.push_back(s.kit->expert_pool()[static_cast<std::size_t>(i)].trial);
  const Diagnosis d = diagnose_trials(*s.kit, trials, 0);
  for (int m = 0; m < d.expertise.num_skills(); ++m) EXPECT_FALSE(d.expertise.penalised(m)) << "skill " << m;
}

// Realistic learners (teaching/tasks/writing_planted_weakness.hpp) with one letter written badly, at a seed
// none of docs/skills.md's tables uses: quality-aware expertise finds the letter at least as often as Alg. 2
// and in nearly every learner (measured: 15 of 15; Alg. 2 13 of 15).
TEST(PlantedWeakness, WritingQualityAwareExpertiseFindsTheBadlyWrittenLetterUnderRealisticNoise) {
  ASSERT_TRUE(std::filesystem::exists(shipped_writing_model()));
  const WritingSetup& s = writing_setup();
  auto measure = [&](ExpertiseMode mode) {
    const PlantedWeaknessReport r = measure_planted_weaknesses(*s.kit, ClassicDrawerGlyphs::load(), 3, 3, mode);
    int top = 0;
    for (const PlantedLetterRow& row : r.letters) top += row.top_target;
    std::printf(
        "%s: %d of 15 planted letters are the first target, %d of %d noise-only learners quiet (%d with "
        "no confident drill target)\n",
        expertise_mode_name(mode).c_str(), top, r.noise_without_confident_target, r.noise_learners,
        r.noise_without_confident_drill_target);
    // The drill targets are the ranking without the skills too brief to drill: never weaker than the targets.
    EXPECT_GE(r.noise_without_confident_drill_target, r.noise_without_confident_target);
    EXPECT_LE(r.noise_without_confident_drill_target, r.noise_learners);
    return std::pair{top, r};
  };
  const int quality_aware = measure(ExpertiseMode::QualityAware).first;
  EXPECT_GE(quality_aware, 13);
  EXPECT_GE(quality_aware, measure(ExpertiseMode::Alg2).first);
}

// Letters in another drawer's shape as close to the paper's as noise leaves the paper's own (within the segment
// floor each time), but that shape every time: the repeated floors find them, the segment floor alone does not
// (measured at seed 24, which no table uses, 9 learners per letter: 3 of 4 such learners found, 0 of 4 without;
// noise-only learners 9 of 9 quiet either way).
TEST(PlantedWeakness, WritingRepeatedEvidenceFindsALetterWrittenInACloseShapeEveryTime) {
  ASSERT_TRUE(std::filesystem::exists(shipped_writing_model()));
  const WritingSetup& s = writing_setup();
  ASSERT_TRUE(s.kit->execution_noise_floor().has_value() && s.kit->execution_noise_floor()->repeated_more);
  WritingKitOptions segment_only;
  segment_only.execution_noise_floor = NoiseFloor(s.kit->execution_noise_floor()->segment);
  const WritingKit plain(std::make_shared<CompileExtractor>(CompileExtractor::load(shipped_writing_model(), "writing")),
                         "", segment_only);
  struct Count {
    int found = 0, learners = 0, quiet = 0;
  };
  auto within_the_floor = [&](const WritingKit& kit) {
    const PlantedWeaknessReport r =
        measure_planted_weaknesses(kit, ClassicDrawerGlyphs::load(), 9, 24, ExpertiseMode::QualityAware);
    Count c{0, 0, r.noise_without_confident_target};
    for (const auto& [key, cell] : r.other_drawers)
      if (cell.shape_score > r.noise_floor->segment) c.found += cell.found, c.learners += cell.learners;
    return c;
  };
  const Count repeated = within_the_floor(*s.kit), alone = within_the_floor(plain);
  std::printf("within the segment floor: %d of %d found with the repeated floors, %d of %d without\n", repeated.found,
              repeated.learners, alone.found, alone.learners);
  ASSERT_EQ(repeated.learners, alone.learners);
  ASSERT_GT(repeated.learners, 0);
  EXPECT_GT(repeated.found, alone.found);
  EXPECT_GE(repeated.found, repeated.learners - 1);
  EXPECT_EQ(repeated.quiet, alone.quiet);
}

// Noise-only realistic learners (the planted table's background hand, no fault) at a seed no table uses: with
// the noise floor they get no confident target (measured: 10 of 10; with the outlier cut alone 6 of 10).
TEST(PlantedWeakness, WritingNoiseOnlyLearnersGetNoConfidentTarget) {
  ASSERT_TRUE(std::filesystem::exists(shipped_writing_model()));
  const WritingSetup& s = writing_setup();
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  const std::vector<std::string> words = pretest_words(*s.kit);
  int quiet = 0;
  const int learners = 10;
  for (int i = 0; i < learners; ++i) {
    const PlantedLearner learner = noise_only_learner(23, i);
    const Diagnosis d = diagnose_trials(*s.kit, planted_pretest_trials(glyphs, words, learner), learner.seed,
                                        s.kit->learners_expertise());
    double lowest = 0.0;
    for (int m : d.expertise.targets) lowest = std::min(lowest, d.expertise.expertise[static_cast<std::size_t>(m)]);
    quiet += lowest >= kConfidentTargetExpertise;
  }
  std::printf("%d of %d noise-only learners without a confident target\n", quiet, learners);
  EXPECT_GE(quiet, learners - 1);
}

}  // namespace
}  // namespace sc
