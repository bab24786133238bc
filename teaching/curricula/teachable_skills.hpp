#pragma once
// Which skills are worth teaching on their own. The paper filtered out "skills corresponding to
// trajectories below a minimum length (due to human perceptual limits)"; the reference code drops a latent
// whose segments are all shorter than 2 steps. Here a skill is teachable when at least one of its expert
// segments has `min_steps` or more control steps. A skill that is not teachable is never a target and never
// practised alone, but it may still appear inside a drill between teachable ones (its motion is real, just
// too brief to watch and copy in isolation). The task kits choose min_steps (docs/skills.md, "Teaching rounds").
#include <utility>
#include <vector>

#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// True when some segment of `skill` in the pool is at least min_steps long.
bool is_teachable(int skill, const std::vector<Segmentation>& pool, int min_steps);

// (skill, number of segments at least min_steps long), most segments first, ties: lower id. Skills without
// such a segment are left out.
std::vector<std::pair<int, int>> teachable_by_frequency(const std::vector<Segmentation>& pool, int min_steps);

// The diagnosis' ranking (weakest first) without the skills that are not teachable.
std::vector<int> teachable_ranking(const ExpertiseEstimate& diagnosis, const std::vector<Segmentation>& pool,
                                   int min_steps);

}  // namespace sc
