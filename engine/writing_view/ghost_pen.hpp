#pragma once
// The ghost pen: the expert writing the word at the expert's pace (writing::kExpertStepsPerSecond steps of
// <= 1 px per second, the pace the expert's trial files are time-stamped with), so a learner can watch how a
// character is written - where it starts, the order and direction of its strokes, where the pen lifts.
// Pure timing and geometry; canvas_painter.hpp draws it.
#include <span>
#include <vector>

#include "engine/render/draw_types.hpp"
#include "engine/writing/trace_point.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::writing_view {

struct GhostPenFrame {
  std::vector<writing::TracePoint> written;  // the path up to the pen tip, the tip itself last
  Vec2f tip;
  bool pen_down = true;   // the tip is drawing (false while it moves lifted between strokes)
  double progress = 0.0;  // 0 at the start, 1 when the word is finished
  bool finished = false;
};

// Seconds the ghost pen needs for a path of `points` points (points - 1 steps).
double ghost_pen_duration(std::size_t points, double steps_per_second = writing::kExpertStepsPerSecond);

// Where the ghost pen is `seconds` after it started; the tip moves linearly within a step. Before the start
// (seconds <= 0) it rests on the first point; after the end it rests on the last with the whole path written.
// An empty path gives an empty, finished frame.
GhostPenFrame ghost_pen_at(std::span<const writing::TracePoint> path, double seconds,
                           double steps_per_second = writing::kExpertStepsPerSecond);

}  // namespace sc::writing_view
