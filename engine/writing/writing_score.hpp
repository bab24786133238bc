#pragma once
// The writing task's reward: how much the learner's ink overlaps the gold (expert) ink.
// The paper only says "degree of overlap with the gold trajectory, <= 0, 0 optimal"; the authors' code has
// no implementation, so this is our definition (docs/writing-score.md has the formula and a picture):
//
//   ink      = the pen-down segments of a trace (pen-up moves are not ink), resampled by arc length every
//              `spacing_px`; infilling with the reference rule only inserts midpoints on straight
//              segments, so it does not change the ink, and arc-length resampling makes the score
//              independent of how often the learner's pen was sampled.
//   credit(d)= 1 for d <= tolerance, falling linearly to 0 at d = cutoff, 0 beyond.
//   recall   = mean credit of the gold samples, d = distance to the nearest learner ink sample
//              (how much of the word was written: an unfinished word loses recall);
//   precision= mean credit of the learner samples, d = distance to the nearest gold ink sample
//              (how much of the learner's ink lies on the word: scribbles and offsets lose precision);
//   score    = recall * precision - 1, in [-1, 0]; 0 only when every gold sample is within `tolerance`
//              of learner ink and every learner sample within `tolerance` of gold ink.
// The product (rather than the F-measure, also reported) makes the score proportional to the fraction of
// the word completed: a perfect half word scores -0.5 (the F-measure would give -0.33).
#include <cstddef>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/writing/trace_point.hpp"

namespace sc::writing {

struct WritingScoreParams {
  double tolerance_px = 3.0;         // full credit band around the gold ink
  double cutoff_px = 8.0;            // no credit from here on
  double spacing_px = 0.5;           // arc-length resampling step
  std::size_t max_samples = 400000;  // per ink set; longer ink is resampled more coarsely
};

struct WritingScore {
  double score = -1.0;  // recall * precision - 1
  double recall = 0.0;
  double precision = 0.0;
  double f_measure = 0.0;  // 2PR / (P + R), for reference
  double gold_ink_px = 0.0;
  double learner_ink_px = 0.0;
  std::size_t gold_samples = 0;
  std::size_t learner_samples = 0;
};

// Samples every `spacing` px along the ink (pen-down segments) of a trace; a run's start and end are always
// sampled and a dot (zero-length inked segment) gives one sample. `ink_length` receives the total length.
std::vector<Point2> resample_ink(const std::vector<TracePoint>& trace, double spacing, double* ink_length = nullptr);

// gold: the expert's trace (WordTrajectory::points()); learner: the learner's trace, raw or infilled.
// Throws std::invalid_argument when the gold has no ink.
WritingScore score_writing(const std::vector<TracePoint>& gold, const std::vector<TracePoint>& learner,
                           const WritingScoreParams& params = {});

Json writing_score_json(const WritingScore& score, const WritingScoreParams& params);

}  // namespace sc::writing
