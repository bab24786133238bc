#pragma once
// The reference's infill rule (reference-facts §2.4 step 3), used for the characters AND for learners'
// traces: walk i from 0; while the step p_i -> p_{i+1} moves more than 1 px in y or in x, insert the midpoint
// (p_i + p_{i+1}) / 2 at i + 1 and re-check the same i. Afterwards every step has |dx| <= 1 and |dy| <= 1.
// Inserting midpoints on straight segments never changes the drawn polyline, only its sampling.
#include <cstddef>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/writing/trace_point.hpp"

namespace sc::writing {

std::vector<Point2> infill_reference(const std::vector<Point2>& points);

// Same rule on a pen trace with optional time stamps (times.empty() or times.size() == points.size()).
// An inserted midpoint inherits the pen state of the segment it splits and the mean of its end times.
struct TimedTrace {
  std::vector<TracePoint> points;
  std::vector<double> times;  // seconds; empty when the trace has no time stamps
};
TimedTrace infill_trace(const TimedTrace& trace);

// Reference §2.4 step 5: while fewer than `min_points`, insert the midpoint of a random pair (p_i, p_{i+1}).
// The reference inserted it at index i (before p_i: a bug that creates a back-step); we fix it and insert
// between p_i and p_{i+1}. It never triggers for the paper's characters (all have >= 410 points).
std::vector<Point2> pad_to_min_points(std::vector<Point2> points, std::size_t min_points, Rng& rng);

}  // namespace sc::writing
