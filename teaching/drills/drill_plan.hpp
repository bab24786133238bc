#pragma once
// A drill (or any practice material) as a task-agnostic plan: a sequence of expert segments, each naming
// the expert trajectory and the [begin, end) action interval to play. The task turns a plan into
// something playable through a DrillProjector (parking: re-simulate the concatenated actions from the
// first segment's initial state; writing: translate each pen segment to start where the previous ended).
#include <array>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct DrillSegment {
  int skill = 0;   // skill id this segment demonstrates (for time-heuristic material: the slice id)
  int expert = 0;  // index of the expert trajectory in the pool the plan was built from
  int begin = 0;   // half-open action interval [begin, end) of that trajectory
  int end = 0;
  int length() const { return end - begin; }
  bool operator==(const DrillSegment&) const = default;
};

struct DrillPlan {
  int target_skill = -1;               // the weak skill m* this drill is for; -1 when not individualized
  std::vector<int> ngram;              // skill sequence of one repetition
  int ngram_count = 0;                 // f(x) of that sequence in the expert pool (0: not from the table)
  int repetitions = 1;                 // N_rep: how often the sequence is repeated inside the drill
  std::vector<DrillSegment> segments;  // ngram.size() x repetitions segments, in play order

  int length() const;               // total action steps
  std::vector<int> skills() const;  // skill of each segment, in play order
  // Start index of each segment in the stitched trajectory (prefix sums of the lengths).
  std::vector<int> segment_starts() const;
  bool operator==(const DrillPlan&) const = default;
};

// The plan's skills laid end to end over [0, length()): the "expert segmentation" of the drill, e.g. to
// run Alg. 2 on a learner's attempt at the drill (Adaptive curriculum) or to colour the ghost path.
Segmentation plan_segmentation(const DrillPlan& plan);

// The initial state of a drill is the state before the first segment's first action (the paper's choice;
// the dynamics are deterministic, so state + actions define the whole drill). Throws InputError for an
// empty plan, an expert index out of range or an interval outside the trajectory.
std::vector<float> drill_initial_state(const DrillPlan& plan, const std::vector<StepSequence>& experts);

// The expert states and actions of every segment copied end to end, without any stitching (projectors
// start from this). Validates indices, intervals and that all experts share state/action dimensions.
StepSequence concatenate_expert_steps(const DrillPlan& plan, const std::vector<StepSequence>& experts);

// What the app plays: the stitched trajectory and its ghost path.
struct PlayableDrill {
  DrillPlan plan;
  StepSequence steps;                             // states[t] before actions[t]; states[0] = initial state
  std::vector<float> final_state;                 // state after the last action (state_dim values)
  std::vector<std::array<double, 2>> ghost_path;  // x, y per state incl. the final one, task units
  std::vector<int> segment_starts;                // where each plan segment begins in steps
  double drill_return = 0.0;                      // the task's own return for the stitched trajectory
  bool success = false;                           // the task's own success criterion for it
};

// Implemented by each task (parking, writing); must be deterministic.
class DrillProjector {
 public:
  virtual ~DrillProjector() = default;
  virtual PlayableDrill project(const DrillPlan& plan) const = 0;
};

}  // namespace sc
