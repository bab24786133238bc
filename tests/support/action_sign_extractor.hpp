#pragma once
// A skill extractor for tests that reads one action axis: each step's skill is the sign of that action
// (0: below -0.1, 1: between, 2: above +0.1), runs of one skill merged. A model that reads actions, with no
// training; it records the length of every trajectory it is given.
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc::test {

class ActionSignExtractor final : public SkillExtractor {
 public:
  explicit ActionSignExtractor(int axis) : axis_(axis) {}
  Segmentation extract(const StepSequence& x) const override {
    lengths.push_back(x.length());
    Segmentation out;
    for (int t = 0; t < x.length(); ++t) {
      const float u = x.actions[static_cast<std::size_t>(t * x.action_dim + axis_)];
      const int skill = u < -0.1f ? 0 : u > 0.1f ? 2 : 1;
      if (!out.segments.empty() && out.segments.back().skill == skill)
        out.segments.back().end = t + 1;
      else
        out.segments.push_back({skill, t, t + 1});
    }
    return out;
  }
  int num_skills() const override { return 3; }
  std::string name() const override { return axis_ == 0 ? "pedal-sign" : "steering-sign"; }
  mutable std::vector<int> lengths;

 private:
  int axis_;
};

}  // namespace sc::test
