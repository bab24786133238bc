#pragma once
// Turns real frame time into a whole number of fixed simulation sub-steps (1/15 s each), so the simulation
// is deterministic whatever the frame rate. Time beyond `max_frame_seconds` in one frame is dropped rather
// than caught up: after the window was minimised for an hour, a debugger stop or a device-lost pause, the
// car continues from where it was instead of jumping ahead. The caller simply does not call
// advance() while a trial is paused.
namespace sc::input {

class SubstepClock {
 public:
  // Throws InputError unless 0 < substep_seconds <= max_frame_seconds (both finite).
  explicit SubstepClock(double substep_seconds = 1.0 / 15.0, double max_frame_seconds = 0.25);

  // Adds one frame's elapsed real time (negative or NaN counts as 0) and returns how many sub-steps are
  // due now (at most max_frame_seconds / substep_seconds + 1).
  int advance(double frame_seconds);
  // Forgets accumulated time (new trial, or resuming after a pause).
  void reset() { accumulated_ = 0.0; }
  // Fraction of a sub-step already elapsed, in [0, 1): for interpolating the drawn car between sub-steps.
  double phase() const { return accumulated_ / substep_seconds_; }

 private:
  double substep_seconds_;
  double max_frame_seconds_;
  double accumulated_ = 0.0;
};

}  // namespace sc::input
