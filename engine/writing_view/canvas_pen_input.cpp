#include "engine/writing_view/canvas_pen_input.hpp"

#include <algorithm>

#include "engine/writing_view/canvas_geometry.hpp"

namespace sc::writing_view {

writing::PenSample pen_sample_at(const Camera2D& camera, const PointerSample& sample) {
  const Vec2f canvas = camera.pixel_to_world(sample.pixels);
  return {sample.time, static_cast<double>(canvas.x), static_cast<double>(canvas.y), sample.pressed};
}

bool on_canvas(const Camera2D& camera, Vec2f pixels) {
  const Vec2f p = camera.pixel_to_world(pixels);
  const WorldRect canvas = canvas_rect();
  return p.x >= canvas.min_x && p.x <= canvas.max_x && p.y >= canvas.min_y && p.y <= canvas.max_y;
}

CanvasPenInput::CanvasPenInput(writing::PenRecorderRules rules) : rules_(rules) {}

double CanvasPenInput::monotonic(double time) {
  if (last_time_) time = std::max(time, *last_time_);
  last_time_ = time;
  return time;
}

void CanvasPenInput::feed(const PointerSample& sample, const Camera2D& camera, bool may_press) {
  if (ended() || paused()) return;
  const bool starts_stroke = sample.pressed && !drawing();
  if (starts_stroke && (!may_press || !on_canvas(camera, sample.pixels))) return;
  if (!recorder_) {
    if (!sample.pressed) return;  // hovering before the first stroke is not recorded
    recorder_.emplace(monotonic(clock(sample.time)), rules_);
  }
  PointerSample s = sample;
  s.time = monotonic(clock(sample.time));
  recorder_->add(pen_sample_at(camera, s));
}

void CanvasPenInput::done(double time) {
  const double t = monotonic(clock(time));
  if (!recorder_) recorder_.emplace(t, rules_);
  recorder_->done(t);
}

void CanvasPenInput::tick(double time) {
  if (recorder_ && !paused()) recorder_->tick(monotonic(clock(time)));
}

void CanvasPenInput::pause(double time) {
  if (!paused()) paused_at_ = time;
}

void CanvasPenInput::resume(double time) {
  if (!paused()) return;
  paused_total_ += std::max(0.0, time - *paused_at_);
  paused_at_.reset();
}

double CanvasPenInput::seconds_left(double time) const {
  return recorder_ ? recorder_->seconds_left(clock(time)) : rules_.time_limit_seconds;
}

writing::TimedTrace CanvasPenInput::raw() const { return recorder_ ? recorder_->raw() : writing::TimedTrace{}; }

writing::TimedTrace CanvasPenInput::infilled() const {
  return recorder_ ? recorder_->infilled() : writing::TimedTrace{};
}

}  // namespace sc::writing_view
