#pragma once
// Fine-tuning data of the synthetic-student experiment: the (state, action) pairs a study condition's
// practice material holds, cut to the same size for every condition (the paper: "using an equal dataset
// size"). The material comes from the curricula module (make_curriculum), so the experiment's conditions
// are the app's conditions:
//   Ind. Drills      Alg. 3 drills for the student's weakest skills (N_target of them), rounds of one
//                    drill per target with fresh random expert segments;
//   Drills           random drills from the offline drill set;
//   Full Trajectory  whole expert demonstrations in a seeded random order.
// Every drill segment contributes its own expert's states and actions (bc_dataset_from_plan): a drill
// re-simulated from its first segment plays all actions against the LAST segment's goal, which would pair
// earlier segments' actions with a goal they were not planned for and teach the student wrong actions.
#include <cstdint>
#include <vector>

#include "teaching/curricula/curriculum.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

struct FinetuneMaterial {
  std::vector<StepSequence> expert_steps;   // the expert pool's demos (DrillSegment::expert indexes these)
  std::vector<Segmentation> expert_skills;  // the SkillExtractor's segmentation of each demo
  ExpertiseEstimate diagnosis;              // Alg. 2 on the student's rollouts (Ind. Drills targets)
  int num_targets = 3;                      // the paper: the student's 3 weakest skills
};

struct FinetuneData {
  StudyCondition condition = StudyCondition::IndDrills;
  std::vector<PracticeItem> items;  // the material the pairs come from, in order (the last one may be cut)
  BcDataset pairs;                  // exactly the requested size (when the material exists)
};

// The pairs of one round of Ind. Drills — one drill per target, the paper's "fixed set of 3 drills" — for
// this seed: the experiment's default data size. InputError when the diagnosis ranks no skill.
int individualized_round_pairs(const FinetuneMaterial& material, std::uint64_t seed);

// `pairs` pairs of the condition's material (IndDrills, Drills or FullTrajectory; InputError otherwise or
// for pairs < 1). Deterministic in seed; material is drawn until it holds at least `pairs` pairs.
FinetuneData finetune_data(StudyCondition condition, const FinetuneMaterial& material, int pairs, std::uint64_t seed);

}  // namespace sc
