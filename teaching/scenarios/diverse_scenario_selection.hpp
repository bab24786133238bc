#pragma once
// Alg. 1 of the paper (diverse scenario selection): greedy maximum coverage of the expert's skills over a
// pool of expert scenarios, so that a few pre-test scenarios exercise as many different skills as possible.
// Task-agnostic: it only sees the expert's segmentation of each pool scenario.
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// Why one scenario was picked (kept so the app and the docs can explain the choice).
struct ScenarioPick {
  int scenario = 0;     // index into the pool
  int new_skills = 0;   // skills it added to the covered set (the paper's criterion)
  int new_bigrams = 0;  // ordered pairs of consecutive skills it added (first tie-break)
  int redundancy = 0;   // sum over its distinct skills of how many earlier picks already showed them
  bool operator==(const ScenarioPick&) const = default;
};

struct ScenarioSelection {
  std::vector<ScenarioPick> picks;     // in pick order
  std::vector<int> covered_skills;     // sorted union of the picked scenarios' skills
  std::vector<int> scenarios() const;  // the pool indices, in pick order
};

// Picks min(count, pool size) distinct scenarios. Each step takes the unpicked scenario that maximises,
// in this order (lexicographic; each criterion only breaks ties of the previous ones):
//   1. new_skills   = |covered ∪ M_ξ| − |covered|     (the paper's argmax; with many skills uncovered
//                                                       this alone decides)
//   2. new_bigrams  = skill transitions (m_i, m_i+1) not shown by an earlier pick: once every skill is
//                     covered, criterion 1 is 0 for all and this keeps adding *combinations* of skills,
//                     which is what drills are built from (Alg. 3)
//   3. -redundancy  = prefer scenarios whose skills were shown least often so far (spreads the evidence
//                     Alg. 2 gets over the skills instead of piling it on a few)
//   4. -index       = lowest pool index (deterministic, independent of hashing or sort stability).
// Scenarios with an empty segmentation are valid (they score 0). Throws InputError when count < 0.
ScenarioSelection select_diverse_scenarios(const std::vector<Segmentation>& expert_pool, int count);

}  // namespace sc
