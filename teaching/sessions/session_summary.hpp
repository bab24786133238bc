#pragma once
// What the summary screen shows for one round: pre-test vs evaluation score, the improvement and how each
// skill's expertise changed (Alg. 2 on the pre-test vs Alg. 2 on the evaluation, both against the expert's
// segmentation of their own scenarios; the same number of trials keeps the two comparable).
#include <map>
#include <string>
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

struct SkillChange {
  int skill = 0;
  double before = 0.0;      // E_m on the pre-test (<= 0, 0 = no mistakes seen)
  double after = 0.0;       // E_m on this round's evaluation
  bool drilled = false;     // practised in this round: a target of a drill or a skill item that was played
  int practice_trials = 0;  // how many practice trials of this round targeted it (extra attempts included)
  bool seen = false;        // the expert used it in the pre-test or evaluation scenarios
};

struct RoundSummary {
  int round = 1;
  double pretest_mean = 0.0;  // mean task reward (<= 0, 0 best)
  double eval_mean = 0.0;
  double improvement = 0.0;         // eval_mean - pretest_mean: > 0 means closer to the expert
  int practice_trials = 0;          // practice trials played this round (extra attempts included)
  std::vector<SkillChange> skills;  // every skill the kit knows, by id
};

// How a skill changed, as the summary shows it (E_m to two decimals): a learner reads "-0.20 -> -0.20" as the
// same, and "0.00 -> 0.00" as no mistake at all, not as an improvement.
enum class SkillTrend { no_mistake, better, same, worse };
SkillTrend skill_trend(const SkillChange& change);
const char* to_string(SkillTrend trend);  // "no mistake", "better", "same", "worse"

double mean_of(const std::vector<double>& values);  // 0 for an empty list

RoundSummary summarize_round(int round, const std::vector<double>& pretest_rewards,
                             const std::vector<double>& eval_rewards, const ExpertiseEstimate& before,
                             const ExpertiseEstimate& after, const std::map<int, int>& trials_per_skill,
                             int practice_trials);

}  // namespace sc
