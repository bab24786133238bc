#pragma once
// A curriculum is the plain, ordered list of practice items a learner plays between pre-test and
// evaluation. Every item is a DrillPlan (expert segments in play order), so a single DrillProjector per
// task makes any item playable: a full trajectory is one expert's segments from 0 to T, a skill is one
// expert segment, a drill is Alg. 3's concatenation.
//
// Conditions (the paper's §5 study arms, plus Adaptive):
//   Full Trajectory  whole expert trajectories, distinct ones in a seeded random order, 1 session each;
//   Time Heuristic   the Skills recipe applied to the time-heuristic segmentation (K equal slices; a
//                    slice index plays the role of a skill id), kind TimeSlice;
//   Skills           the `common_skills` (3) most common skills of the pool (most expert segments first,
//                    ties: lower id), one random expert segment each, `sessions_per_skill` (3) sessions;
//   Drills           random drills from the offline drill set (DrillBuilder::random_drills);
//   Ind. Drills      Alg. 3 drills for the learner's pre-test diagnosis, weakest target first;
//   Adaptive         Ind. Drills in rounds, re-diagnosed after each round (adaptive_curriculum.hpp).
// When a condition runs out of distinct material before the budget is reached it starts another pass
// (fresh random segments, reshuffled order).
//
// Budget rule (equal practice time across conditions, as in the paper): the budget counts control steps
// of practice (item steps x sessions). Sessions are added one at a time in the condition's order while the
// total is below the budget; the session that would cross it is kept only if that lands at least as close
// to the budget as stopping. Hence |total − budget| <= ½ · (longest session offered), and the first session
// is always kept. The default budget (budget_steps = 0) is the Skills condition's natural length for the
// same seed (3 skills x 3 sessions), the paper's reference arm.
#include <cstdint>
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
};

struct CurriculumConfig {
  DrillConfig drills = DrillConfig::parking();
  int budget_steps = 0;             // 0: the Skills condition's natural length (see above)
  int common_skills = 3;            // Skills / Time Heuristic: the 3 most common skills ...
  int sessions_per_skill = 3;       // ... 3 sessions each
  int sessions_per_trajectory = 1;  // Full Trajectory ("3 different full trajectories")
  int sessions_per_drill = 1;
  int adaptive_rounds = 3;          // Adaptive: the budget is split evenly over this many rounds

  static CurriculumConfig parking();  // DrillConfig::parking()
  static CurriculumConfig writing();  // DrillConfig::writing()
  void validate() const;              // InputError for non-positive counts or a negative budget
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
Curriculum make_curriculum(StudyCondition condition, const CurriculumInputs& inputs,
                           const CurriculumConfig& config);

// config.budget_steps if set, else the Skills condition's natural length for inputs.seed.
int curriculum_budget_steps(const CurriculumInputs& inputs, const CurriculumConfig& config);

// Ind. Drills filled to `budget` for a diagnosis (used by Ind. Drills and each Adaptive round).
Curriculum individualized_drill_curriculum(StudyCondition condition, const ExpertiseEstimate& diagnosis,
                                           int budget, const CurriculumInputs& inputs,
                                           const CurriculumConfig& config, Rng& rng);

}  // namespace sc
