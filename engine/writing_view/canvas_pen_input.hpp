#pragma once
// Mouse/trackpad -> pen: turns pointer samples in framebuffer pixels (the window's mouse motion and button
// events, each with its time stamp, plus the mouse state polled once per frame) into canvas-pixel PenSamples
// for the headless writing::PenRecorder, through the canvas camera.
//  * A press starts the pen only on the canvas and when the UI does not own the mouse (`may_press`): a click
//    on a button next to the canvas is not ink. Once down, the pen follows the mouse anywhere, like a pen
//    sliding off the paper, until release.
//  * The trial's clock (and its time limit) starts at the first pen-down, so reading the word first is free.
//  * The trial ends as writing::PenRecorder decides: on release for classic single-stroke words, on done()
//    (the "Done" button or Enter), or at the time limit, which tick() checks every frame.
//  * pause()/resume() stop the trial's clock (the learner pressed Esc): samples while paused are dropped, the
//    time limit does not run, and the trace's times leave the paused span out, as if the pen had waited.
//    A stroke held across the pause goes on (a classic word is not ended by the pause itself).
//  * Time stamps never go backwards: event time stamps have millisecond resolution and the frame's poll time
//    comes from another call, so a sample earlier than the previous one is given the previous one's time.
#include <optional>

#include "engine/render/camera2d.hpp"
#include "engine/writing/pen_recorder.hpp"

namespace sc::writing_view {

struct PointerSample {
  double time = 0.0;  // seconds, one clock for all samples of a trial
  Vec2f pixels;       // framebuffer pixels, top-left origin
  bool pressed = false;
};

// The canvas position under a framebuffer pixel.
writing::PenSample pen_sample_at(const Camera2D& camera, const PointerSample& sample);
// Whether a framebuffer pixel lies on the 500 x 300 canvas.
bool on_canvas(const Camera2D& camera, Vec2f pixels);

class CanvasPenInput {
 public:
  explicit CanvasPenInput(writing::PenRecorderRules rules);

  // One motion/button event or one frame's polled state. `may_press`: the UI does not own the mouse.
  void feed(const PointerSample& sample, const Camera2D& camera, bool may_press = true);
  void done(double time);    // ends the trial now (even before any ink: an empty trial)
  void tick(double time);    // once per frame: the time limit
  void pause(double time);   // no-op when already paused
  void resume(double time);  // no-op when not paused
  bool paused() const { return paused_at_.has_value(); }

  bool started() const { return recorder_.has_value(); }
  bool drawing() const { return recorder_ && recorder_->pressed(); }
  bool ended() const { return recorder_ && recorder_->ended(); }
  writing::TrialEnd end_reason() const { return recorder_ ? recorder_->end_reason() : writing::TrialEnd::NotEnded; }
  // The whole limit before the first pen-down.
  double seconds_left(double time) const;
  const writing::PenRecorderRules& rules() const { return rules_; }
  // The trace so far, times relative to the first pen-down (empty before it).
  writing::TimedTrace raw() const;
  writing::TimedTrace infilled() const;

 private:
  double monotonic(double time);
  // The trial clock: wall time minus every paused span (frozen at the pause while paused).
  double clock(double time) const { return (paused_at_ ? *paused_at_ : time) - paused_total_; }

  writing::PenRecorderRules rules_;
  std::optional<writing::PenRecorder> recorder_;
  std::optional<double> last_time_;
  std::optional<double> paused_at_;
  double paused_total_ = 0.0;
};

}  // namespace sc::writing_view
