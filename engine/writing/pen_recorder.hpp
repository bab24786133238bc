#pragma once
// Records a learner's pen trace from mouse/trackpad input without knowing about SDL: the app feeds it one
// PenSample per frame and per motion/button event (time, position on the canvas, button pressed).
//  * press -> a touch-down point (pen 0: the pen arrived lifted), then one inked point (pen 1) per sample
//    whose position changed; release -> the release position as a last inked point (a tap without motion
//    leaves a dot). Hovering is not recorded.
//  * The trial ends on release when `end_on_release` (classic single-stroke words), on done(), when the time
//    limit has passed (samples after it are ignored), or when kMaxTrialPoints is reached.
//  * infilled() gives the trace infilled with the reference rule, as the authors infilled their users'
//    traces (reference §2.7).
#include <cstddef>

#include "engine/writing/infill.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::writing {

struct PenSample {
  double time = 0.0;  // seconds, any origin; must not go backwards
  double x = 0.0;     // canvas pixels
  double y = 0.0;
  bool pressed = false;
};

struct PenRecorderRules {
  bool end_on_release = true;
  double time_limit_seconds = 60.0;  // from the trial's start time
};
// The rules for a scenario: ends on release for classic words; time limit writing_time_limit_seconds.
PenRecorderRules pen_rules_for(const WordTrajectory& gold);

enum class TrialEnd { NotEnded, Released, Done, TimeLimit, TooLong };

class PenRecorder {
 public:
  PenRecorder(double start_time, PenRecorderRules rules);

  void add(const PenSample& sample);
  void done(double time);  // the learner pressed "done"
  void tick(double time);  // a frame without input: only checks the time limit

  bool ended() const { return end_ != TrialEnd::NotEnded; }
  TrialEnd end_reason() const { return end_; }
  bool pressed() const { return pressed_; }
  double seconds_left(double time) const;
  const TimedTrace& raw() const { return trace_; }  // times relative to the start time
  TimedTrace infilled() const { return infill_trace(trace_); }

 private:
  void append(double x, double y, bool pen, double time);
  bool check_time(double time);

  double start_;
  PenRecorderRules rules_;
  TimedTrace trace_;
  bool pressed_ = false;
  bool moved_since_press_ = false;
  TrialEnd end_ = TrialEnd::NotEnded;
};

}  // namespace sc::writing
