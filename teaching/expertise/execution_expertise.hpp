#pragma once
// Quality-aware expertise (beyond the paper): Alg. 2 only asks whether a skill is present in the learner's
// segmentation, so a skill done recognisably but badly is never diagnosed, and a skill the segmentation
// happens to miss is charged the whole trial's reward. This adds a per-skill execution term:
//
//   E^q_m = E_m (Alg. 2, unchanged)  +  w · Σ_ξ Σ_{j : m^e_j = m} min(0, q_{ξ,j} - min(q̃ - c·s, f)) / j
//
// where q_{ξ,j} <= 0 is the task's own reward of the learner's part aligned (dynamic time warping,
// trace_alignment.hpp) with the expert's j-th segment of trial ξ, relative to a perfect copy (0), q̃ the
// median of the learner's q over all the trials' segments, s their robust standard deviation (scaled
// median absolute deviation), c = kOutlierCut, and f the task's noise floor (below). The 1/j weight is
// Alg. 2's: early skills weigh more. w = kExecutionWeight.
// Why relative to the learner: a learner's input device and hand spoil every segment a little (a mouse's
// corners, a wobble wider than the writing score's 3 px tolerance); a skill is done badly when it is done
// clearly worse than the learner does the rest - an outlier among their own segments, not merely below
// their median (docs/skills.md, "Quality-aware expertise on the writing table").
// Why a noise floor as well: a tidy learner's segments mostly score 0, their spread is then near 0 and any
// slight wobble would stand out. The floor f is what realistic noise alone reaches (a low percentile of
// noise-only learners' segment scores, calibrated per task and model: TaskKit::execution_noise_floor), so
// only what is both unusual for this learner and worse than noise makes is charged. The floor also checks
// Alg. 2's "missing": a skill the segmentation missed in a trial although the learner's aligned part
// scores at or above f is not charged - the learner did it as well as noise allows, the segmenter missed it.
// Without a floor (nullopt) both rules are as without it: the outlier cut alone, every "missing" charged.
// Why repeated evidence: a letter written in another shape every time can stay within what noise does to
// one segment each time, but noise does not spoil the same skill in every segment. So a skill whose median
// score over its segments of the pre-test (the mean of two for two) falls below the floor for medians of
// that many segments (NoiseFloor::repeated_twice / repeated_more, the same percentile of noise-only
// learners' medians) is charged beyond that floor instead, in each of its segments. Only for a learner who
// writes in the expert's hand (no learner's hand taken, below): one whose letters follow a hand of its own
// writes some of them unlike the guide every time by style, not by fault (docs/skills.md, "Repeated
// evidence").
//
// Why the learner's hand: a task may give other right ways of doing the expert's trial (execution_reference.hpp;
// writing: the word in other drawers' hands). The reference whose scores have the highest mean over all of
// the learner's segments, if higher than the expert's own, is taken as the learner's hand (kLearnerHands),
// and each segment's q is the better of its score against the expert and against that hand; then everything
// above. One hand for the whole pre-test, not one per segment: a letter written wrong in every word still
// differs from the hand the rest of the learner's letters follow. And a hand is more than one skill: the
// reference must score higher than the expert even without the skill where it gains most, or a single letter
// written in that reference's shape (a fault, if the learner's other letters are the expert's) would make it
// the yardstick and waive itself (docs/skills.md, "Aligned with the hand itself").
//
// Why each target was chosen is its largest penalty: "missing" (Alg. 2's) or "done with a large error"
// (the execution term), with the trial, the expert's steps and the learner's aligned steps.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

inline constexpr double kExecutionWeight = 1.0;
// The outlier cut: Iglewicz and Hoaglin's modified z-score of 3.5, the usual robust test for "stands out",
// with the median absolute deviation scaled to a normal standard deviation (1.4826). Taken from the
// literature, not fitted to the planted-learner tables.
inline constexpr double kOutlierCut = 3.5;
inline constexpr double kMadToStandardDeviation = 1.4826;
// How many references may be taken as the learner's hand: one. Three (each segment scored against the best
// of them) found three more planted letters at one design seed of two and none at the other (docs/skills.md,
// "The learner's own hand as the yardstick"); one hand waives less.
inline constexpr int kLearnerHands = 1;

// What realistic noise alone does to the execution score, calibrated per task and model
// (teaching/tasks/execution_noise_floor.hpp). A floor of one number is the segment floor alone.
struct NoiseFloor {
  NoiseFloor(double segment_floor = 0.0) : segment(segment_floor) {}  // NOLINT: a floor is a number first
  double segment;                                                     // f: one segment's score
  std::optional<double> repeated_twice;  // a skill's mean score over its 2 segments of a pre-test
  std::optional<double> repeated_more;   // a skill's median score over its 3 or more segments
};
// Skills with this many segments in a pre-test or more take NoiseFloor::repeated_more.
inline constexpr int kRepeatedMore = 3;
// The median of a skill's scores as the repeated floors are calibrated and applied: the mean of the middle
// two for an even count. Throws InputError for no scores.
double median_score(std::vector<double> scores);

enum class ExpertiseMode {
  Alg2,          // the paper's Alg. 2 exactly (research mode)
  QualityAware,  // Alg. 2 plus the execution term
};

// The modes by their names on the command line and in a diagnosis's JSON: "alg2", "quality-aware".
const std::map<std::string, ExpertiseMode>& expertise_modes_by_name();
const std::string& expertise_mode_name(ExpertiseMode mode);

// One expert segment's execution by the learner.
struct SegmentExecution {
  double reward = 0.0;    // q <= 0, against the expert's own way
  int learner_begin = 0;  // the learner's aligned steps [begin, end)
  int learner_end = 0;
  // The same part scored against each of the task's references (TaskKit::execution_references), in the
  // same order in every trial; empty when the task gives none.
  std::vector<double> reference_rewards = {};
};

struct ExecutionTrial {
  ExpertiseTrial trial;                           // what Alg. 2 reads
  std::vector<SegmentExecution> segments;         // parallel to trial.expert.segments
  std::vector<std::string> reference_names = {};  // what each reference_rewards entry was scored against
};

// NoMistake: a target without any penalty (fewer weak skills than targets: Alg. 3 still drills the skills
// the expert relies on); its place is the skill's first expert segment. RepeatedError: charged by repeated
// evidence, so no one segment was far off but every one was; its place is the segment charged most.
enum class TargetReason { Missing, LargeError, NoMistake, RepeatedError };
// "missing", "done with a large error here", "no mistake seen", "done a little wrong every time"
const char* target_reason_words(TargetReason reason);

struct TargetWhy {
  int skill = 0;
  TargetReason reason = TargetReason::Missing;
  int trial = 0;                           // index into the trials given
  int position = 0;                        // j (1-based) in that trial's expert sequence
  double delta = 0.0;                      // the penalty (>= 0)
  int expert_begin = 0, expert_end = 0;    // the expert's segment
  int learner_begin = 0, learner_end = 0;  // the learner's aligned steps (missing: still the aligned part)
};

struct ExecutionExpertise {
  ExpertiseEstimate estimate;      // contributions hold both kinds; an execution one's reward is q
  std::vector<TargetWhy> why;      // one per estimate.targets entry, in that order
  std::vector<int> learner_hands;  // the references taken as the learner's hand, best first; none: the expert's own
};

// mode Alg2: estimate_expertise exactly (why from its penalties; noise_floor unused); QualityAware: the
// formula above, with the learner's hand, the noise floor's two rules and repeated evidence when a floor is
// given (every value <= 0). Throws InputError as estimate_expertise does, and for segments not parallel to the
// expert's, q > 0, a floor > 0 or segments with different numbers of reference scores.
ExecutionExpertise estimate_execution_expertise(const std::vector<ExecutionTrial>& trials, int num_skills,
                                                int num_targets, ExpertiseMode mode,
                                                const std::optional<NoiseFloor>& noise_floor = std::nullopt);

}  // namespace sc
