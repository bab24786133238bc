#include "engine/writing/pen_recorder.hpp"

#include <algorithm>

#include "engine/writing/writing_trial.hpp"

namespace sc::writing {

PenRecorderRules pen_rules_for(const WordTrajectory& gold) {
  return {trial_ends_on_release(gold.alphabet), writing_time_limit_seconds(gold.steps.size())};
}

PenRecorder::PenRecorder(double start_time, PenRecorderRules rules) : start_(start_time), rules_(rules) {}

double PenRecorder::seconds_left(double time) const {
  return std::max(0.0, rules_.time_limit_seconds - (time - start_));
}

bool PenRecorder::check_time(double time) {
  if (ended()) return false;
  if (time - start_ > rules_.time_limit_seconds) {
    end_ = TrialEnd::TimeLimit;
    pressed_ = false;
    return false;
  }
  return true;
}

void PenRecorder::append(double x, double y, bool pen, double time) {
  if (trace_.points.size() >= kMaxTrialPoints) {
    end_ = TrialEnd::TooLong;
    return;
  }
  trace_.points.push_back({x, y, pen});
  trace_.times.push_back(time - start_);
}

void PenRecorder::add(const PenSample& s) {
  if (!check_time(s.time)) return;
  if (s.pressed && !pressed_) {  // pen down: the pen travelled lifted to here
    pressed_ = true;
    moved_since_press_ = false;
    append(s.x, s.y, false, s.time);
  } else if (s.pressed) {  // drawing: frames repeat the position while the hand rests; keep changes only
    const TracePoint& last = trace_.points.back();
    if (s.x != last.x || s.y != last.y) {
      moved_since_press_ = true;
      append(s.x, s.y, true, s.time);
    }
  } else if (pressed_) {  // release
    pressed_ = false;
    const TracePoint& last = trace_.points.back();
    if (!moved_since_press_ || s.x != last.x || s.y != last.y) append(s.x, s.y, true, s.time);
    if (rules_.end_on_release && !ended()) end_ = TrialEnd::Released;
  }
}

void PenRecorder::done(double time) {
  if (!check_time(time)) return;
  if (pressed_ && !trace_.points.empty()) {  // "done" while drawing: close the stroke where the pen is
    pressed_ = false;
    if (!moved_since_press_) append(trace_.points.back().x, trace_.points.back().y, true, time);
  }
  if (!ended()) end_ = TrialEnd::Done;
}

void PenRecorder::tick(double time) { check_time(time); }

}  // namespace sc::writing
