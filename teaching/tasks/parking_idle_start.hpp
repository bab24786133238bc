#pragma once
// A parking drive's skills start when its car starts moving.
//
// Why: a learner's trial is recorded from the moment the countdown ends, and nobody moves the car in that very
// instant: the first control steps of a trial stand still while the learner reacts. The expert's drives, and
// the plans the skill model was trained on, move from their first step. The model reads a standing start as
// part of the manoeuvre: the expert's own motion replayed a reaction delay late agreed with the expert's skills
// on only 89.1 / 87.5 % of the steps at 0.2 s and 81.7 / 75.9 % at 0.3 s, against 99.0 / 97.8 % with no delay
// (docs/skills.md, *A standing start*). Reading the drive from its first moving step removes that.
//
// Spec:
//  * idle_start_steps: the number of leading control steps after which the car is still slower than
//    kIdleStartSpeed (0.5 m/s, half of what one control step at full pedal gives from standing; stick noise
//    of 0.2 held through a whole step gives 0.2 m/s); never the whole drive (the last step is kept);
//  * ParkingIdleStartExtractor wraps another extractor: a drive with k > 0 idle steps is segmented from step k
//    on, every segment moved k steps later and the first one stretched back to step 0 (standing still is no
//    skill of its own: it belongs to the manoeuvre it precedes). A drive that moves from its first step is
//    segmented exactly as by the wrapped extractor. name() and num_skills() are the wrapped extractor's.
#include <memory>
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

inline constexpr double kIdleStartSpeed = 0.5;  // m/s

// `steps` is a parking step sequence (parking_steps.hpp: the 12-D observation, speed from its velocity).
int idle_start_steps(const StepSequence& steps);

class ParkingIdleStartExtractor final : public SkillExtractor {
 public:
  explicit ParkingIdleStartExtractor(std::shared_ptr<const SkillExtractor> inner);

  Segmentation extract(const StepSequence& trajectory) const override;
  std::vector<Segmentation> extract_all(const std::vector<StepSequence>& trajectories) const override;
  int num_skills() const override { return inner_->num_skills(); }
  std::string name() const override { return inner_->name(); }

 private:
  std::shared_ptr<const SkillExtractor> inner_;
};

}  // namespace sc
