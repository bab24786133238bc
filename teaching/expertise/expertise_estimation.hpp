#pragma once
// Alg. 2 of the paper (individual expertise identification), task-agnostic:
//   E_m = −Σ_ξ Δ_m(τ^e_ξ, τ^s_ξ),  Δ_m = −r_ξ(τ^s_ξ) / j  if the expert's j-th skill is m and m is not among
//   the student's skills in ξ, else 0.
// Skills the student never shows although the expert needs them are taken as failed; failures early in the
// expert's sequence weigh more (1, 1/2, 1/3, ...) and low-reward trials weigh more.
//
// Fix of the paper's pseudocode: it sets j ← 0 before the loop and divides before incrementing, i.e. the
// first skill divides by zero. Eq. 3 indexes skills m_1, m_2, ..., so j counts from 1 here (first skill
// weight 1). A skill that occurs several times in the expert's sequence is penalised once per occurrence,
// each with its own position j (as the pseudocode's loop over M^e_ξ does).
//
// Rewards must be <= 0 (optimum 0), as the paper assumes. Task adapters map their scores:
//   parking: the trial's trajectory reward (the reference's episode score is the last step's reward, <= 0);
//   writing: an overlap score s in [0, 1] maps to r = s − 1 (see non_positive_reward).
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// One pre-test (or practice) trial with the expert's segmentation of the same scenario.
struct ExpertiseTrial {
  int scenario = 0;             // the caller's id of the scenario (e.g. pool index); echoed in contributions
  Segmentation expert;          // M^e_ξ, B^e_ξ
  Segmentation student;         // M^s_ξ, B^s_ξ (SkillExtractor on the student's trajectory)
  double student_reward = 0.0;  // r_ξ(τ^s_ξ) <= 0
};

// One penalty, kept so the app can explain a diagnosis ("you never reversed in scenario 4, your 1st skill").
struct ExpertiseContribution {
  int trial = 0;        // index into the trials given to estimate_expertise
  int scenario = 0;     // that trial's scenario id
  int position = 0;     // j: 1-based position of the skill in the expert's sequence
  double reward = 0.0;  // r_ξ(τ^s_ξ)
  double delta = 0.0;   // Δ_m = −reward / j >= 0 (E_m = −Σ delta)
  // Quality-aware expertise (execution_expertise.hpp): the skill was shown but done worse than the learner's
  // other skills; then `reward` is that segment's execution score and delta = −w·reward / j.
  bool execution = false;
  // ... charged by repeated evidence: done worse than noise makes in every segment of the skill, each by a
  // little; then `reward` is q beyond the floor for medians (execution_expertise.hpp).
  bool repeated = false;
  bool operator==(const ExpertiseContribution&) const = default;
};

struct ExpertiseEstimate {
  std::vector<double> expertise;  // E_m per skill id, <= 0; lower = weaker
  std::vector<int> occurrences;   // how often m occurs in the trials' expert sequences (0: no evidence)
  std::vector<std::vector<ExpertiseContribution>> contributions;  // per skill, in trial order
  // Every skill with occurrences > 0, weakest first. Ties: lower E first, then the skill the expert used
  // more often (more relevant, more evidence), then the lower skill id. Skills absent from every expert
  // sequence carry no evidence and are never ranked or targeted.
  std::vector<int> ranking;
  std::vector<int> targets;  // the first N_target entries of ranking (fewer if fewer skills were seen)
  // Quality-aware expertise only: the reference taken as the learner's hand (execution_expertise.hpp), e.g.
  // "the letters of Omniglot drawer 5"; empty when the execution term measured against the expert alone.
  std::string learner_hand;

  int num_skills() const { return static_cast<int>(expertise.size()); }
  // True when the skill lost expertise (at least one penalty with a nonzero reward).
  bool penalised(int skill) const;
};

// Alg. 2 over the given trials. num_skills bounds the skill ids (ids must lie in [0, num_skills)).
// Throws InputError naming the trial for a positive or non-finite reward or an out-of-range skill id.
ExpertiseEstimate estimate_expertise(const std::vector<ExpertiseTrial>& trials, int num_skills, int num_targets);

// Orders seen skills and fills ranking/targets from expertise and occurrences (rule above).
void rank_expertise(ExpertiseEstimate& estimate, int num_targets);

// Maps a task score whose best possible value is `best` to a reward <= 0 (r = score − best, capped at 0).
double non_positive_reward(double score, double best);

}  // namespace sc
