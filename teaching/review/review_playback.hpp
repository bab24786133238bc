#pragma once
// Playback of a trial in the review (play, pause, scrub, speed 0.25x-4x) as plain state, so the screen only
// draws it: the position is in steps (fractional), advanced by the simulation's fixed time step.
#include <array>

namespace sc::review {

inline constexpr std::array<double, 5> kPlaybackSpeeds = {0.25, 0.5, 1.0, 2.0, 4.0};

class Playback {
 public:
  // A trial of `steps` steps, each `step_seconds` long at 1x. Starts paused at the end (the whole path).
  void load(int steps, double step_seconds);
  void play();  // from the start when at the end
  void pause() { playing_ = false; }
  void toggle() { playing_ ? pause() : play(); }
  void scrub(double position);   // clamped to [0, steps]
  void set_speed(double speed);  // clamped to [0.25, 4]
  // Advances by `dt` seconds of wall time; stops at the end.
  void advance(double dt);

  bool playing() const { return playing_; }
  double position() const { return position_; }  // steps
  double seconds() const { return position_ * step_seconds_; }
  double speed() const { return speed_; }
  int steps() const { return steps_; }
  // The step whose input is being applied at the current position (for the input stick).
  int current_step() const;

 private:
  int steps_ = 0;
  double step_seconds_ = 0.2;
  double position_ = 0.0;
  double speed_ = 1.0;
  bool playing_ = false;
};

}  // namespace sc::review
