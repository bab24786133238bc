#include "engine/core/fixed_step_clock.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace sc {

FixedStepClock::FixedStepClock(double step_seconds, int max_steps_per_frame)
    : step_(step_seconds), max_steps_(max_steps_per_frame) {
  if (!(step_seconds > 0) || !std::isfinite(step_seconds))
    throw InputError("FixedStepClock", "step must be a positive number of seconds");
  if (max_steps_per_frame < 1) throw InputError("FixedStepClock", "max_steps_per_frame must be at least 1");
}

ClockAdvance FixedStepClock::advance(double elapsed_seconds) {
  if (!std::isfinite(elapsed_seconds) || elapsed_seconds < 0) elapsed_seconds = 0;
  accumulator_ += elapsed_seconds;
  ClockAdvance result;
  // A tiny epsilon so that e.g. 3 frames of exactly 1/60 s give 3 steps despite rounding.
  const double whole = std::floor(accumulator_ / step_ + 1e-9);
  if (whole > max_steps_) {
    result.steps = max_steps_;
    const double kept = accumulator_ - max_steps_ * step_;
    // Same rounding allowance as above, so an exact multiple of the step leaves nothing behind.
    const double remainder = std::max(0.0, kept - std::floor(kept / step_ + 1e-9) * step_);
    result.dropped_seconds = kept - remainder;
    accumulator_ = remainder;
  } else {
    result.steps = static_cast<int>(whole);
    accumulator_ = std::max(0.0, accumulator_ - whole * step_);
  }
  result.alpha = std::min(accumulator_ / step_, 1.0 - 1e-12);
  return result;
}

}  // namespace sc
