#pragma once
// The Adaptive condition (ours; the paper's appendix names repeating Alg. 2 during practice as future
// work): individualized drills in rounds. After each round the learner's practice trials are segmented,
// Alg. 2 runs on them (the expert sequence of a drill trial is the drill plan's own skill sequence), the
// rounds are merged with latest_evidence_expertise, and the next round's drills target the new weakest
// skills. Round 0 targets the pre-test diagnosis exactly as Ind. Drills does.
//
// Size: by default every round is a weak_skill_round (2 unique drills for each of the 3 weakest teachable
// skills); the first one draws the same drills as Ind. Drills, so a round practises the reference budget.
// With an explicit budget each round gets ceil(budget / config.adaptive_rounds) steps instead. next_round
// keeps producing rounds (the app offers "another adaptive round").
#include <vector>

#include "teaching/curricula/curriculum.hpp"

namespace sc {

struct AdaptiveRound {
  ExpertiseEstimate evidence;   // Alg. 2 on the trials that led to this round (round 0: the pre-test)
  ExpertiseEstimate diagnosis;  // what this round targets (round 0: the pre-test; later: merged rounds)
  Curriculum practice;          // this round's drills, condition Adaptive
};

// Round 0 from inputs.pretest.
AdaptiveRound first_adaptive_round(const CurriculumInputs& inputs, const CurriculumConfig& config);

// The next round after `previous` (non-empty, oldest first) given the learner's trials of the last round.
// new_trials may be empty (the learner skipped practice): the diagnosis is then unchanged. Random segment
// choices use a stream forked by round index, so the whole sequence is deterministic in inputs.seed.
AdaptiveRound next_round(const std::vector<AdaptiveRound>& previous, const std::vector<ExpertiseTrial>& new_trials,
                         const CurriculumInputs& inputs, const CurriculumConfig& config);

// The Alg. 2 input for a learner's attempt at a practice item: the item's plan laid end to end is the
// expert side (plan_segmentation), `learner` is the SkillExtractor's segmentation of the attempt and
// `reward` its task reward (<= 0). `scenario` is echoed in the diagnosis (e.g. the item index).
ExpertiseTrial practice_trial(const PracticeItem& item, Segmentation learner, double reward, int scenario);

}  // namespace sc
