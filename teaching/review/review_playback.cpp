#include "teaching/review/review_playback.hpp"

#include <algorithm>
#include <cmath>

namespace sc::review {

void Playback::load(int steps, double step_seconds) {
  steps_ = std::max(0, steps);
  step_seconds_ = step_seconds > 0.0 ? step_seconds : 0.2;
  position_ = steps_;
  playing_ = false;
}

void Playback::play() {
  if (position_ >= steps_) position_ = 0.0;
  playing_ = steps_ > 0;
}

void Playback::scrub(double position) { position_ = std::clamp(position, 0.0, static_cast<double>(steps_)); }

void Playback::set_speed(double speed) { speed_ = std::clamp(speed, kPlaybackSpeeds.front(), kPlaybackSpeeds.back()); }

void Playback::advance(double dt) {
  if (!playing_) return;
  position_ += dt * speed_ / step_seconds_;
  if (position_ >= steps_) {
    position_ = steps_;
    playing_ = false;
  }
}

int Playback::current_step() const {
  if (steps_ == 0) return 0;
  return std::clamp(static_cast<int>(std::floor(position_)), 0, steps_ - 1);
}

}  // namespace sc::review
