#pragma once
// Behaviour-cloning pairs for the synthetic students: goal-conditioned (state, action) pairs cut from
// expert step sequences (the 12-D parking observation already holds the goal), and the two manipulations
// the experiment needs: dropping most reverse-acceleration pairs ("reversing difficulty" student) and
// cutting a data set to an exact size (equal-size fine-tuning data across study conditions).
#include <cstdint>
#include <vector>

#include "teaching/drills/drill_plan.hpp"
#include "teaching/skills/skill_extractor.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

// Every (states[t], actions[t]) pair of the sequences, in order. InputError when dimensions differ.
BcDataset bc_dataset_from_steps(const std::vector<StepSequence>& sequences);

// The pairs a plan's expert segments hold, each segment's states taken from its own expert trajectory
// (concatenate_expert_steps): every pair keeps the goal its action was planned for.
BcDataset bc_dataset_from_plan(const DrillPlan& plan, const std::vector<StepSequence>& experts);

// Pairs whose first action component (parking: acceleration u0) is negative.
int count_reverse_pairs(const BcDataset& data);

// Keeps every pair with u0 >= 0 and round(keep_fraction x R) of the R pairs with u0 < 0, chosen uniformly
// without replacement by sc::Rng(seed); the kept pairs stay in their original order. The paper's
// "only 20 % of the data containing reverse acceleration actions" read as: 20 % of those pairs are kept
// (reference-facts §5 notes the wording is ambiguous). InputError unless 0 <= keep_fraction <= 1.
BcDataset keep_reverse_fraction(const BcDataset& data, double keep_fraction, std::uint64_t seed);

// The first `count` pairs (all of them when there are fewer).
BcDataset first_pairs(const BcDataset& data, int count);

// `count` pairs drawn uniformly without replacement by sc::Rng(seed) (all of them, in order, when there are
// fewer); the drawn pairs keep their original order.
BcDataset sample_pairs(const BcDataset& data, int count, std::uint64_t seed);

}  // namespace sc
