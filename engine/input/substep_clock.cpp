#include "engine/input/substep_clock.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"

namespace sc::input {

SubstepClock::SubstepClock(double substep_seconds, double max_frame_seconds)
    : substep_seconds_(substep_seconds), max_frame_seconds_(max_frame_seconds) {
  if (!std::isfinite(substep_seconds) || !std::isfinite(max_frame_seconds) || substep_seconds <= 0.0 ||
      max_frame_seconds < substep_seconds)
    throw InputError("substep clock", "needs 0 < substep (" + std::to_string(substep_seconds) +
                                          " s) <= max frame time (" + std::to_string(max_frame_seconds) + " s)");
}

int SubstepClock::advance(double frame_seconds) {
  if (!(frame_seconds > 0.0)) return 0;  // also NaN
  accumulated_ += std::min(frame_seconds, max_frame_seconds_);
  int due = 0;
  while (accumulated_ >= substep_seconds_) {
    accumulated_ -= substep_seconds_;
    ++due;
  }
  return due;
}

}  // namespace sc::input
