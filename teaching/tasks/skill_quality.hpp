#pragma once
// Segmentation quality of a task's skills (evaluate-skills), measured against what the tasks know:
//  * writing: the true character boundaries of generated words; a predicted boundary counts when it lies
//    within +-5 % of the word's length (in steps) of a not yet matched true boundary;
//  * parking: skill purity - for each skill, the share of its steps that reverse vs drive forward and that
//    steer left vs right vs straight. A skill that mixes all of them teaches nothing specific.
#include <map>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/skills/segmentation_metrics.hpp"
#include "teaching/tasks/skill_training_data.hpp"

namespace sc {

inline constexpr double kWritingBoundaryTolerance = 0.05;  // fraction of the word's length

// Sum over demos of score_boundaries(interior predicted, demo.true_boundaries, round(fraction * T)).
// `predicted` is parallel to `demos`; demos without true boundaries are skipped.
BoundaryScore writing_boundary_score(const std::vector<Segmentation>& predicted, const std::vector<SkillDemo>& demos,
                                     double tolerance_fraction = kWritingBoundaryTolerance);

// Steering |u1| at most this is "straight" (u1 in [-1, 1] maps to +-45 degrees: 0.1 is 4.5 degrees).
inline constexpr double kStraightSteering = 0.1;

struct ParkingStepKind {
  bool reversing = false;  // signed speed after the step (before it for the last step) is negative
  int turn = 0;            // +1 left (u1 > kStraightSteering), -1 right, 0 straight
};
// Reads a parking StepSequence (12-D observations, see parking_steps.hpp) at step t.
ParkingStepKind classify_parking_step(const StepSequence& steps, int t);

struct ParkingSkillPurity {
  int skill = 0;
  int steps = 0;
  double reversing = 0.0, forward = 0.0;           // shares of the skill's steps, sum to 1
  double left = 0.0, right = 0.0, straight = 0.0;  // shares, sum to 1
  double direction_purity() const { return reversing > forward ? reversing : forward; }
  double turn_purity() const;  // the largest of left, right, straight
};

struct ParkingPurityReport {
  std::vector<ParkingSkillPurity> skills;  // skills with at least one step, by id
  double direction_purity = 0.0;           // step-weighted mean of the skills' direction purity
  double turn_purity = 0.0;                // step-weighted mean of the skills' turn purity
};

// `segmentations` parallel to `trajectories`. Throws InputError if a trajectory is not 12-D/2-D.
ParkingPurityReport parking_skill_purity(const std::vector<Segmentation>& segmentations,
                                         const std::vector<StepSequence>& trajectories);

// Writing: which symbols each skill draws. A demo's label is its word (one character per symbol) and its
// true boundaries split it into those symbols, so every step has a true symbol. A skill drawing one
// symbol only (purity 1) is what a drill for "the letter a" needs; one skill for several letters would
// drill them together.
struct WritingSkillSymbols {
  int skill = 0;
  int steps = 0;
  std::map<char, int> symbol_steps;  // true symbol -> steps of this skill on it
  char majority() const;             // the symbol with the most steps (the smaller character on a tie)
  double purity() const;             // share of the skill's steps on its majority symbol
};
struct WritingSymbolReport {
  std::vector<WritingSkillSymbols> skills;  // skills with at least one step, by id
  double purity = 0.0;                      // step-weighted mean of the skills' purity
  std::map<char, int> symbol_skill;         // each symbol -> the skill drawing most of its steps
};
// Demos without true boundaries, or whose label does not have one character per symbol, are skipped.
WritingSymbolReport writing_symbol_purity(const std::vector<Segmentation>& segmentations,
                                          const std::vector<SkillDemo>& demos);

Json to_json(const BoundaryScore& score);
Json to_json(const WritingSymbolReport& report);
Json to_json(const ParkingPurityReport& report);

// What evaluate-skills prints for `segmentations` (parallel to data.demos): {"task", "trajectories",
// "steps", "usage" (skill_usage.hpp), and "boundaries" and "symbols" (writing, when true boundaries are
// known: to_json(BoundaryScore) plus "tolerance", to_json(WritingSymbolReport)) or "purity" (parking)}.
Json skill_quality_report(const SkillDataSet& data, const std::vector<Segmentation>& segmentations);

}  // namespace sc
