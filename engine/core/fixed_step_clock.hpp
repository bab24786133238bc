#pragma once
// Fixed simulation timestep with an accumulator ("Fix your timestep"): each rendered frame adds its real
// elapsed time, runs as many whole simulation steps as fit, and renders with `alpha`, the fraction of a step
// left over, to interpolate between the previous and current simulation states.
// No spiral of death: a long frame (window minimised, debugger, slow disk) runs at most `max_steps_per_frame`
// steps and the rest of the time is dropped, so the simulation slows down instead of falling ever further behind.
namespace sc {

struct ClockAdvance {
  int steps = 0;               // simulation steps to run this frame
  double alpha = 0;            // in [0, 1): render state = previous + alpha * (current - previous)
  double dropped_seconds = 0;  // time discarded by the clamp (0 in normal frames)
};

class FixedStepClock {
 public:
  // Throws InputError unless step_seconds > 0 and max_steps_per_frame >= 1.
  FixedStepClock(double step_seconds, int max_steps_per_frame);

  // Adds a frame's elapsed wall time (negative or non-finite counts as 0).
  ClockAdvance advance(double elapsed_seconds);
  void reset() { accumulator_ = 0; }

  double step_seconds() const { return step_; }
  int max_steps_per_frame() const { return max_steps_; }
  // Simulation time not yet consumed by a step, in [0, step).
  double pending_seconds() const { return accumulator_; }

 private:
  double step_;
  int max_steps_;
  double accumulator_ = 0;
};

}  // namespace sc
