#pragma once
// Segment colours of one `skillcoach segment --png` picture (kept apart from the GL drawing so it can be
// unit-tested without a context).
#include <vector>

#include "engine/render/draw_types.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc::cli {

// The colours of one picture: the skills in order of first appearance get the colours of a list of 12 that
// stay readable on the dark lot and on the light paper (cycling after 12 skills in one picture). A colour
// per skill id across pictures would need 24 hues for the writing model, and some were too pale to see on
// the paper or too close to tell apart (two greens); the legend names each segment's skill id.
class SkillColors {
 public:
  explicit SkillColors(const Segmentation& segmentation);
  // A skill that does not appear in the segmentation gets the colour after the last one used.
  Color of(int skill) const;

 private:
  std::vector<int> order_;  // skill ids by first appearance
};

}  // namespace sc::cli
