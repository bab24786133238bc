#pragma once
// Augmented parking data: a skill model trained only on the planner's clean drives labels a novice's noisy,
// delayed or keyboard-quantised copy of the same manoeuvre with other skills (docs/skills.md, "Robustness on
// realistic learners: parking"), and Alg. 2 then counts those skills as missing. Training on realistic copies
// beside the clean drives shows CompILE the input real learners give.
//
// Spec. Expert plans on parking_pool_scenario(seed, i), i < count, as generate_parking_demos (plans that do
// not park are left out); after each clean plan, `copies` realistic drives of it (realistic_driver.hpp): the
// device drawn uniformly from gamepad / mouse joystick / keyboard, a novice profile (sample_novice_profile:
// stick noise 0.05-0.2, reaction delay 0.1-0.3 s), 15 Hz input, no planted deficit. Copy c of plan i uses
// Rng(seed).fork(kAugmentStream).fork(i).fork(c + 1), so the data are reproducible and independent of the
// evaluation's drivers (other seeds, other streams). Copies that collide are kept: learners collide too.
// No boundaries are known or inherited (parking training has no warm start).
// With `keyed_copy`, each plan also gets one copy with every action replaced by the keys a keyboard gives for
// it (keyboard_keys) on the clean plan's states: the same motion read through keyboard values, so the model
// learns that key values alone do not make another skill (docs/skills.md, "Why the keyboard rows disagree").
#include <cstdint>

#include "teaching/tasks/skill_training_data.hpp"

namespace sc {

SkillDataSet generate_augmented_parking_demos(int count, int copies, std::uint64_t seed, bool keyed_copy = false);

}  // namespace sc
