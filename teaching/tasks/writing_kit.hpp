#pragma once
// TaskKit for writing (the paper's classic alphabet by default): the expert pool is a set of distinct
// generated words with their gold trajectories; drills are the stitched pen path on the canvas.
//
// Reward mapping (Alg. 2 needs r <= 0, 0 best): score_writing already gives s = recall x precision - 1
// in [-1, 0] (docs/writing-score.md); r = non_positive_reward(s, 0) = min(s, 0), i.e. the score itself,
// capped at 0 against rounding. A perfect trace has r = 0, an empty or unrelated one r = -1.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/writing/word_trajectory.hpp"
#include "teaching/sessions/task_kit.hpp"
#include "teaching/tasks/writing_drill_projector.hpp"
#include "teaching/tasks/writing_execution.hpp"
#include "teaching/tasks/writing_hand_references.hpp"
#include "teaching/tasks/writing_skill_places.hpp"

namespace sc {

inline constexpr int kWritingTimeSlices = 8;  // the paper's study: K = 8 for writing

struct WritingKitOptions {
  std::filesystem::path data_dir;  // Omniglot stroke files; empty = writing::omniglot_data_dir()
  writing::AlphabetKind alphabet = writing::AlphabetKind::Classic;
  int pool_words = 30;  // distinct words (the classic generator has 60 in all)
  std::uint64_t seed = 0;
  // Quality-aware expertise's noise floor: the one recorded with the extractor's model
  // (writing_noise_floor.hpp); none for a model without one or the time heuristic.
  std::optional<NoiseFloor> execution_noise_floor;
};

// Distinct words drawn from the alphabet's generator with Rng(seed) (classic: generate_classic_words
// one pair at a time; balinese: generate_balinese_word), skipping `exclude` and repeats. Returns fewer
// than `count` only when 10000 draws found no more (the classic generator has 60 distinct words).
std::vector<std::string> distinct_words(writing::AlphabetKind alphabet, int count, std::uint64_t seed,
                                        const std::vector<std::string>& exclude);

class WritingKit final : public TaskKit {
 public:
  WritingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
             const WritingKitOptions& options = {});

  std::string task() const override { return "writing"; }
  const SkillExtractor& extractor() const override { return *extractor_; }
  std::string extractor_notice() const override { return extractor_notice_; }
  const std::vector<ExpertDemo>& expert_pool() const override { return demos_; }
  const DrillProjector& projector() const override { return *projector_; }
  // CurriculumConfig::writing() with min_skill_steps = 30: 30 infilled pen steps, 30-42 px of path.
  CurriculumConfig curriculum_config() const override;

  StepSequence steps_of(const Json& trial) const override;
  // non_positive_reward(score_writing(gold of the trial's scenario, the trial's points).score, 0).
  double reward_of(const Json& trial) const override;
  Json expert_trial(const Json& scenario) const override;
  // Scenarios of distinct_words(alphabet, count, seed, words of `exclude`).
  std::vector<Json> fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const override;
  std::string describe_skill(int skill) const override;
  // writing_time_limit_seconds: 15 ms per gold pen step, at least 3 s (engine/writing/writing_scenario.hpp).
  double time_limit_seconds(int expert_steps) const override;
  Json drill_trial(const PlayableDrill& drill) const override;
  // Overlap of the attempt's ink with the drill's pen path, mapped like reward_of.
  double drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const override;
  // (x, y) of the pen; the writing score's overlap credit between the expert's segment and the learner's
  // aligned pen points (writing_execution.hpp).
  std::vector<TracePoint3> trace_points(const StepSequence& steps) const override;
  // WritingKitOptions::execution_noise_floor: calibrated with the kit's model (writing_noise_floor.hpp).
  std::optional<NoiseFloor> execution_noise_floor() const override { return options_.execution_noise_floor; }
  // Quality-aware: it finds the letter a learner writes badly for 89-99 of 100 planted learners, Alg. 2 for
  // 57-60, because a badly written letter is usually still segmented as that letter (docs/skills.md).
  ExpertiseMode learners_expertise() const override { return ExpertiseMode::QualityAware; }
  double execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path, int begin,
                          int end) const override;
  // Classic words: the word in the hands of drawers 1-10 (writing_hand_references.hpp); none for Balinese.
  std::vector<ExecutionReference> execution_references(const Json& scenario, const StepSequence& expert) const override;

  const std::vector<WritingSkillPlace>& skill_places() const { return places_; }
  const std::vector<writing::WordTrajectory>& gold_words() const { return golds_; }
  // The symbols a drill's segments come from, in play order, repeats of a symbol in a row merged (at
  // most 10: a drill trial's scenario word).
  std::string drill_word(const DrillPlan& plan) const;

 private:
  std::shared_ptr<const SkillExtractor> extractor_;
  std::string extractor_notice_;
  WritingKitOptions options_;
  std::vector<writing::WordTrajectory> golds_;
  std::vector<ExpertDemo> demos_;
  std::vector<WritingSkillPlace> places_;
  std::vector<std::string> descriptions_;  // describe_skill's words, distinct among used skills
  std::unique_ptr<WritingDrillProjector> projector_;
  std::unique_ptr<WritingHandReferences> hands_;
};

}  // namespace sc
