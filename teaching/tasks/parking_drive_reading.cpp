#include "teaching/tasks/parking_drive_reading.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "teaching/skills/piecewise_extractor.hpp"
#include "teaching/tasks/parking_moving_part.hpp"

namespace sc {

int longest_moving_drive(const std::vector<StepSequence>& drives) {
  int longest = 1;
  for (const StepSequence& d : drives) longest = std::max(longest, moving_part_length(d));
  return longest;
}

std::shared_ptr<const SkillExtractor> parking_drive_reader(std::shared_ptr<const SkillExtractor> model,
                                                           int piece_length, ParkingDriveReading reading) {
  if (!model) throw InputError("parking skill reading", "no skill extractor");
  std::shared_ptr<const SkillExtractor> out = std::move(model);
  const bool in_pieces = !reading.whole_drive && !reading.one_piece && !out->slices_by_time();
  if (in_pieces) out = std::make_shared<PiecewiseExtractor>(out, piece_length);
  if (!reading.whole_drive) out = std::make_shared<ParkingMovingPartExtractor>(out);
  return out;
}

}  // namespace sc
