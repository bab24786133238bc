#pragma once
// A curriculum is the plain, ordered list of practice items a learner plays between pre-test and
// evaluation. Every item is a DrillPlan (expert segments in play order), so a single DrillProjector per
// task makes any item playable: a full trajectory is one expert's segments from 0 to T, a skill is one
// expert segment, a drill is Alg. 3's concatenation.
//
// Conditions (the paper's §5 study arms, plus Adaptive):
//   Full Trajectory  whole expert trajectories, distinct ones in a seeded random order, 1 session each;
//   Time Heuristic   the time-heuristic segmentation (K equal slices; a slice index plays the role of a
//                    skill id): `common_skills` (3) different slice indices drawn per learner (seeded),
//                    `sessions_per_skill` (3) sessions each, kind TimeSlice;
//   Skills           the `common_skills` (3) most common teachable skills of the pool (most expert segments
//                    first, ties: lower id), one random expert segment each, `sessions_per_skill` (3) sessions;
//   Drills           random drills from the offline drill set (DrillBuilder::random_drills);
//   Ind. Drills      a round of `drills_per_weak_skill` (2) unique Alg. 3 drills for each of the
//                    `weak_skills` (3) weakest teachable skills of the pre-test diagnosis, weakest first;
//   Adaptive         such rounds, re-diagnosed after each round (adaptive_curriculum.hpp).
// Teachable: a skill with an expert segment of at least `min_skill_steps` (teachable_skills.hpp).
// When a condition runs out of distinct material before the budget is reached it starts another pass
// (fresh random segments, reshuffled order).
//
// Budget (budget_steps = 0, the default: equal practice time across arms, as in the paper): the reference
// arm is Ind. Drills — its round for this pre-test (the same segments make_curriculum(IndDrills) draws)
// sets the budget B in control steps, so Ind. Drills and Adaptive's first round practise exactly B. The
// other arms take sessions in their order while the total is below B·(1 − budget_tolerance); a session
// that would pass B·(1 + budget_tolerance) is skipped together with the rest of its item and the next
// item is tried; after 200 such misses in a row the last session taken is given back (whole trajectories
// can all be longer than the gap left). With the default tolerance of 4.5 % any two arms differ by less than 10 %.
// An explicit budget (budget_steps > 0; the synthetic students use it) keeps the older rule: sessions are
// added while the total is below the budget, the crossing one only if that lands at least as close to it,
// and Ind. Drills repeats its drills until the budget is filled.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "teaching/curricula/study_condition.hpp"
#include "teaching/drills/drill_builder.hpp"
#include "teaching/expertise/expertise_estimation.hpp"

namespace sc {

enum class PracticeKind { FullTrajectory, TimeSlice, Skill, Drill };
std::string_view practice_kind_key(PracticeKind kind);  // "full-trajectory", "time-slice", "skill", "drill"

struct PracticeItem {
  PracticeKind kind = PracticeKind::Drill;
  // Skills this item is meant to teach: Drill (individualized): {m*}; random Drill: the n-gram's distinct
  // skills; Skill: {m}; TimeSlice: {slice index}; FullTrajectory: the trajectory's distinct skills.
  std::vector<int> target_skills;
  DrillPlan material;  // expert trajectory indices and [begin, end) segments, in play order
  int sessions = 1;    // practice trials of this item (demo + practice each, in the app)

  int steps() const { return material.length(); }  // control steps of one session
  int total_steps() const { return steps() * sessions; }
  bool operator==(const PracticeItem&) const = default;
};

struct Curriculum {
  StudyCondition condition = StudyCondition::FullTrajectory;
  int budget_steps = 0;  // the budget it was filled to
  std::vector<PracticeItem> items;
  int total_steps() const;
  int trials() const;  // sum of the items' sessions
};

// How many played practice trials targeted each skill, `played` holding the item index of each played
// trial: the target_skills of Drill and Skill items. Whole trajectories and time slices practise no skill
// on their own, so they count for none. What "(drilled, N trials)" and the review's outlines show.
std::map<int, int> practice_trials_per_skill(const Curriculum& curriculum, const std::vector<int>& played);

struct CurriculumConfig {
  DrillConfig drills = DrillConfig::parking();
  int budget_steps = 0;             // 0: the reference arm's length (Ind. Drills, see above)
  int common_skills = 3;            // Skills / Time Heuristic: the 3 most common skills ...
  int sessions_per_skill = 3;       // ... 3 sessions each
  int sessions_per_trajectory = 1;  // Full Trajectory ("3 different full trajectories")
  int sessions_per_drill = 1;
  int adaptive_rounds = 3;          // Adaptive with an explicit budget: split evenly over this many rounds
  int weak_skills = 3;              // Ind. Drills / Adaptive round: the 3 weakest teachable skills ...
  int drills_per_weak_skill = 2;    // ... 2 unique drills each (the paper's user study)
  int min_skill_steps = 1;          // teachable: a segment this long; 1 = every skill (kits set their own)
  double budget_tolerance = 0.045;  // default budget: every arm within ±4.5 % of the reference

  static CurriculumConfig parking();  // DrillConfig::parking()
  static CurriculumConfig writing();  // DrillConfig::writing()
  void validate() const;  // InputError for non-positive counts, a negative budget or tolerance outside [0, 0.5]
};

struct CurriculumInputs {
  // SkillExtractor segmentation of each expert trajectory available for practice; the index is the
  // expert index used in every DrillSegment (callers keep evaluation scenarios out of this pool).
  std::vector<Segmentation> expert_skills;
  // TimeHeuristicExtractor segmentation of the same trajectories (needed by Time Heuristic only).
  std::vector<Segmentation> expert_time_slices;
  ExpertiseEstimate pretest;  // Alg. 2 on the learner's pre-test (needed by Ind. Drills and Adaptive)
  std::uint64_t seed = 0;
};

// The curriculum of a condition (for Adaptive: its first round). Deterministic in inputs.seed.
// Throws InputError when the condition's material is missing (empty pool, no time slices for Time
// Heuristic, a pre-test without ranked skills for Ind. Drills / Adaptive).
Curriculum make_curriculum(StudyCondition condition, const CurriculumInputs& inputs, const CurriculumConfig& config);

// config.budget_steps if set, else the reference arm's length: the Ind. Drills round for inputs.pretest.
int curriculum_budget_steps(const CurriculumInputs& inputs, const CurriculumConfig& config);
// Where the budget comes from, in words: "Ind. Drills, 2 drills for each of the 3 weakest skills" or
// "set to 400 steps".
std::string budget_reference(const CurriculumConfig& config);

// One round of drills for `diagnosis`: config.drills_per_weak_skill unique drills for each of the
// config.weak_skills weakest teachable skills that occur in an expert n-gram, weakest first, each
// config.sessions_per_drill sessions. budget_steps is its own length. InputError when no skill qualifies.
Curriculum weak_skill_round(StudyCondition condition, const ExpertiseEstimate& diagnosis,
                            const CurriculumInputs& inputs, const CurriculumConfig& config, Rng& rng);

// The Rng stream make_curriculum uses for a condition (Adaptive's first round shares Ind. Drills' stream).
Rng curriculum_rng(const CurriculumInputs& inputs, StudyCondition condition);

// Ind. Drills filled to `budget` for a diagnosis (explicit budgets only; see above).
Curriculum individualized_drill_curriculum(StudyCondition condition, const ExpertiseEstimate& diagnosis, int budget,
                                           const CurriculumInputs& inputs, const CurriculumConfig& config, Rng& rng);

}  // namespace sc
