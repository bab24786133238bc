#pragma once
// Alg. 3 of the paper (individualized drill creation), task-agnostic: for each of the N_target weakest
// skills, the N_drills most frequent skill n-grams containing it, each skill replaced by a randomly chosen
// expert segment of that skill, the sequence repeated N_rep times. Also the paper's random "Drills"
// condition, drawn from the offline drill set (one drill per skill). Output plans name expert segments;
// a task's DrillProjector makes them playable.
#include <vector>

#include "engine/core/rng.hpp"
#include "teaching/drills/drill_plan.hpp"
#include "teaching/drills/skill_ngrams.hpp"
#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

struct DrillConfig {
  int ngram_length = 3;       // n
  int repetitions = 1;        // N_rep
  int num_targets = 7;        // N_target: how many of the weakest skills get drills
  int drills_per_target = 1;  // N_drills
  // Segments shorter than this are used only for a skill that has no segment this long (CompILE emits
  // 1-step filler segments that make poor practice). 1 = no preference (the paper).
  int min_segment_length = 1;
  // Ours: when a weaker target already got an n-gram, a later target takes its next most frequent n-gram
  // instead, so the learner does not practise the same skill sequence twice (the study gave "unique
  // drills"). When the target has fewer unused n-grams than N_drills, its most frequent ones fill up (with
  // freshly drawn segments, so the drills still differ): every target that occurs in some n-gram gets
  // N_drills drills. false = literal.
  bool distinct_ngrams = true;

  static DrillConfig parking() { return {3, 1, 7, 1, 1, true}; }  // the paper's Parking values
  static DrillConfig writing() { return {2, 3, 8, 1, 1, true}; }  // the paper's Writing values
  void validate() const;                                          // InputError for values < 1
};

class DrillBuilder {
 public:
  // expert_pool[i] is the SkillExtractor segmentation of expert trajectory i; DrillSegment::expert
  // refers to these indices. Throws InputError for a bad config or a segment with a negative skill id.
  DrillBuilder(std::vector<Segmentation> expert_pool, DrillConfig config);

  const DrillConfig& config() const { return config_; }
  const SkillNgramTable& ngrams() const { return ngrams_; }
  const std::vector<Segmentation>& expert_pool() const { return pool_; }
  // Every non-empty expert segment of a skill, in pool order (empty when the skill never occurs).
  std::vector<DrillSegment> segments_of(int skill) const;
  // One expert segment of the skill drawn uniformly (rng.below) among those at least min_segment_length
  // long (among all of them when none is). InputError when the skill has no segment.
  DrillSegment random_segment(int skill, Rng& rng) const;

  // Alg. 3 for the first config().num_targets skills of estimate.ranking (weakest first); drills come out
  // weakest target first, N_drills per target, most frequent n-gram first. Targets that occur in no
  // expert n-gram of the pool get no drill.
  std::vector<DrillPlan> individualized(const ExpertiseEstimate& estimate, Rng& rng) const;
  std::vector<DrillPlan> for_targets(const std::vector<int>& targets, Rng& rng) const;

  // The offline drill set: for each skill of the pool (ascending id) its N_drills most frequent n-grams,
  // duplicates removed (first occurrence kept).
  std::vector<SkillNgram> offline_ngrams() const;
  // `count` random drills (target_skill = -1): n-grams drawn from offline_ngrams() without replacement,
  // reshuffled when exhausted, each projected with fresh random segments.
  std::vector<DrillPlan> random_drills(int count, Rng& rng) const;

  // Projects a skill sequence: each skill gets one uniformly drawn expert segment (rng.below), and the
  // whole sequence is repeated config().repetitions times with the *same* segments (the paper's
  // ⊕_{i=1..N_rep} ⊕_{m∈x} τ^e_m: repetition builds muscle memory of one concrete motion).
  DrillPlan project(const SkillNgram& gram, int target_skill, Rng& rng) const;

 private:
  std::vector<Segmentation> pool_;
  DrillConfig config_;
  SkillNgramTable ngrams_;
};

}  // namespace sc
