#pragma once
// The state of free writing practice without any UI: the word (generated from the run's seed, or typed), its
// gold (expert) path, the trial being written with the mouse, and the scored result. The free-write screen
// draws it and feeds it input.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/writing/writing_score.hpp"
#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/canvas_pen_input.hpp"
#include "engine/writing_view/scripted_trace.hpp"

namespace sc {

struct FreeWriteResult {
  writing::WritingTrial trial;  // the infilled trace, time-stamped, with its score
  writing::WritingScore score;
  writing::TrialEnd end = writing::TrialEnd::NotEnded;
  double seconds = 0;  // from the first pen-down to the last sample
};

class FreeWriteSession {
 public:
  // Starts with generated word number 0 of the classic alphabet. Throws InputError when the stroke data is
  // missing.
  explicit FreeWriteSession(std::uint64_t seed);

  // The next generated word of `kind` (word n of a seeded sequence: the same seed gives the same words).
  void next_generated_word(writing::AlphabetKind kind);
  // Uses a typed word; returns the problem (nothing changes) or an empty string.
  std::string use_word(writing::AlphabetKind kind, const std::string& word);

  // A fresh pen for the current word (the previous result is kept until the new trial ends).
  void restart_trial();
  // Scores the trial once the pen input has ended; returns true when a new result was made.
  bool finish_if_ended();
  // Headless screenshots: a scripted hand writes the word (no input), and the result is scored as usual.
  void write_scripted(const writing_view::ScriptedHand& hand);

  const writing::WritingScenario& scenario() const { return scenario_; }
  const std::vector<writing::TracePoint>& gold_points() const { return gold_points_; }
  std::size_t gold_steps() const { return gold_points_.empty() ? 0 : gold_points_.size() - 1; }
  writing_view::CanvasPenInput& pen() { return pen_; }
  const writing_view::CanvasPenInput& pen() const { return pen_; }
  const std::optional<FreeWriteResult>& result() const { return result_; }
  // The ink to show: the live trace while a trial is under way, else the last result's.
  std::vector<writing::TracePoint> ink() const;
  int generated_count() const { return generated_; }

 private:
  void set_scenario(writing::WritingScenario scenario);
  void score(writing::TimedTrace trace, writing::TrialEnd end);

  std::uint64_t seed_;
  int generated_ = 0;
  writing::WritingScenario scenario_;
  writing::WordTrajectory gold_;
  std::vector<writing::TracePoint> gold_points_;
  writing_view::CanvasPenInput pen_;
  std::optional<FreeWriteResult> result_;
};

// What the learner is told to do for a scenario ("Release the button to finish" for classic words, ...).
const char* free_write_instructions(writing::AlphabetKind kind);
// "released", "done", "time limit", "too long".
const char* trial_end_text(writing::TrialEnd end);

}  // namespace sc
