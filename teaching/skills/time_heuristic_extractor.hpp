#pragma once
// The paper's "Time Heuristic" baseline: K segments of (nearly) equal length, skill id = segment index.
// Fixes two bugs of the reference's get_time_split_frames: its intervals come out in reverse order
// (skill 0 got the *last* slice) and it crashes for T < K or drops slices when floor(T/s) > K.
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

class TimeHeuristicExtractor final : public SkillExtractor {
 public:
  explicit TimeHeuristicExtractor(int num_segments) : k_(num_segments < 1 ? 1 : num_segments) {}
  Segmentation extract(const StepSequence& trajectory) const override;
  int num_skills() const override { return k_; }
  std::string name() const override { return "time-heuristic"; }
  bool slices_by_time() const override { return true; }

 private:
  int k_;
};

}  // namespace sc
