#pragma once
// A parking drive is read where its car moves: standing still before the first move and after the last is no skill.
//
// Why: the trainer records a parking trial from the end of its countdown until the car parks, crashes or the time
// limit (twice the expert's time and 5 s more) runs out, and nobody moves the car in the first instant, nor after
// giving up on a spot. The expert's drives, and the plans the skill model was trained on, move from their first step
// to their last. The model reads standing still as part of the manoeuvre: the expert's own motion replayed 0.2 s late,
// with no noise, agreed with the expert's skills on only 89.1 / 87.5 % of the steps, against 99.0 / 97.8 % on time;
// planted learners who stand a second first, or five seconds at the end, lost much of their diagnosis (docs/skills.md,
// *A standing start*, *Standing at the end*). Reading the drive from its first to its last moving step removes that.
//
// Spec:
//  * standing_start_steps: the number of leading control steps after which the car is still slower than
//    kStandingSpeed (0.5 m/s, half of what one control step at full pedal gives from standing; stick noise of 0.2
//    held through a whole step gives 0.2 m/s);
//  * standing_end_steps: the number of trailing control steps before and after which the car is slower than
//    kStandingSpeed (after the last step: before it); the step that brakes to a stop is not one of them;
//  * together they never take the whole drive: at least one step is read;
//  * ParkingMovingPartExtractor wraps another extractor: a drive with k standing steps at its start and e at its end
//    is segmented on steps [k, T - e), every segment moved k steps later, the first one stretched back to step 0 and
//    the last one on to step T (standing still belongs to the manoeuvre it precedes or follows). A drive that moves
//    from its first step to its last is segmented exactly as by the wrapped extractor. name() and num_skills() are
//    the wrapped extractor's.
#include <memory>
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

inline constexpr double kStandingSpeed = 0.5;  // m/s

// `steps` is a parking step sequence (parking_steps.hpp: the 12-D observation, speed from its velocity); 0 for
// any other kind of sequence.
int standing_start_steps(const StepSequence& steps);
int standing_end_steps(const StepSequence& steps);
// The steps ParkingMovingPartExtractor reads of `steps` (the whole length for any other kind of sequence).
int moving_part_length(const StepSequence& steps);

class ParkingMovingPartExtractor final : public SkillExtractor {
 public:
  explicit ParkingMovingPartExtractor(std::shared_ptr<const SkillExtractor> inner);

  Segmentation extract(const StepSequence& trajectory) const override;
  std::vector<Segmentation> extract_all(const std::vector<StepSequence>& trajectories) const override;
  int num_skills() const override { return inner_->num_skills(); }
  std::string name() const override { return inner_->name(); }

 private:
  std::shared_ptr<const SkillExtractor> inner_;
};

}  // namespace sc
