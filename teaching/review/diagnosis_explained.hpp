#pragma once
// "Diagnosis explained": why the trainer chose the skills it drilled in round 1. The kit's expertise (Alg. 2,
// or quality-aware for writing: TaskKit::learners_expertise) is recomputed (teaching/expertise) from the
// stored pre-test trials against the expert's segmentation of the same scenarios, and for each targeted skill
// the pre-test trials that missed it (or, quality-aware, did it badly) are listed with their Δ
// (Δ = −r / j: r the trial's reward, j the skill's position in the expert's sequence; done badly: −q / j). The
// recomputed expertise is compared with the stored diagnosis, so a model or extractor change since the session shows.
// Each targeted skill also says where its largest penalty happened (the trial and the learner's steps aligned with
// the expert's segment), as the trainer's diagnosis page pictures it.
#include <optional>
#include <string>
#include <vector>

#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/review/trial_review.hpp"
#include "teaching/sessions/learner_hand_traces.hpp"

namespace sc::review {

struct MissedSkillTrial {
  int seq = 0;             // the pre-test trial
  int position = 0;        // j, 1-based position of the skill in the expert's sequence
  double reward = 0.0;     // r of the learner's trial (execution: the segment's execution score q)
  double delta = 0.0;      // Δ = −r / j
  bool execution = false;  // quality-aware expertise: shown but done badly, not missing
  bool repeated = false;   // ... a little off in every segment of the skill (repeated evidence)
};

// Where a skill's largest penalty happened (TargetWhy), with what it takes to picture it.
struct SkillPlace {
  int seq = 0;            // the pre-test trial
  int learner_begin = 0;  // the learner's steps aligned with the expert's segment [begin, end)
  int learner_end = 0;
  int learner_steps = 0;                        // the trial's step count
  TargetReason reason = TargetReason::Missing;  // missing, or done with a large error
  Json learner_trial;                           // the learner's trial document
  Json expert_trial;                            // the expert's trial of the same scenario
};

struct SkillExplanation {
  int skill = 0;
  std::string description;
  double expertise = 0.0;                // recomputed E_m = −Σ Δ
  int occurrences = 0;                   // how often the expert used the skill in these scenarios
  std::vector<MissedSkillTrial> missed;  // trial order
  std::optional<SkillPlace> place;       // none when nothing was charged
};

struct DiagnosisExplanation {
  int round = 1;
  std::vector<int> stored_targets;       // as the trainer stored them
  std::vector<int> recomputed_targets;   // Alg. 2 now
  std::vector<SkillExplanation> skills;  // the stored targets, in their order
  int pretest_trials = 0;
  bool matches_stored = false;  // recomputed expertise equals the stored vector (to 1e-9) with the same targets
  std::string extractor;        // the stored diagnosis's extractor name
  ExpertiseMode mode = ExpertiseMode::Alg2;  // the kit's learners_expertise(), with which it is recomputed
  std::string learner_hand;  // quality-aware: the hand the learner was also scored against (empty: the expert's)
  std::optional<LearnerHandTraces> hand_traces;  // with a hand: the first pre-test trial, its guide and that hand
};

// Throws InputError when the session has no pre-test trials or no round-1 diagnosis.
DiagnosisExplanation explain_diagnosis(const SessionReview& review);

}  // namespace sc::review
