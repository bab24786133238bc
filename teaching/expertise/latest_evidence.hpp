#pragma once
// Expertise for the Adaptive curriculum (ours; the paper names re-running Alg. 2 during practice as future
// work). After each drill round Alg. 2 runs again on that round's trials; this file merges the rounds.
//
// Rule: a skill's expertise is taken from the *latest* round whose expert sequences contain it, divided by
// its number of occurrences in that round (mean penalty per occurrence). Why:
//  - latest: a skill the learner now performs must stop being a target, so older penalties are dropped
//    once new evidence exists; skills not practised this round keep their last measurement;
//  - per occurrence: rounds have different numbers of trials (5 pre-test scenarios vs a few drills), and
//    plain sums would make a skill look weaker just because it was practised more often.
// The result is an ExpertiseEstimate whose `expertise` holds these per-occurrence means (<= 0),
// `occurrences`/`contributions` come from the round each skill was taken from (contribution.trial indexes
// that round's trials), and ranking/targets follow rank_expertise's rule.
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

// rounds: Alg. 2 estimates, oldest first (round 0 is usually the pre-test). All must have the same number
// of skills (InputError otherwise). Returns an empty-ranking estimate when rounds is empty.
ExpertiseEstimate latest_evidence_expertise(const std::vector<ExpertiseEstimate>& rounds, int num_targets);

}  // namespace sc
