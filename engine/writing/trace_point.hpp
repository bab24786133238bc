#pragma once
// Plain geometry shared by the writing task: canvas points and pen-trace points.
// Canvas coordinates are pixels with x to the right and y DOWN (image coordinates), canvas 500 x 300.

namespace sc::writing {

inline constexpr double kCanvasWidth = 500.0;   // DRAWING_WIDTH in the reference
inline constexpr double kCanvasHeight = 300.0;  // DRAWING_HEIGHT
inline constexpr double kStartX = 0.0;          // every word starts at the left edge ...
inline constexpr double kStartY = 150.0;        // ... at the vertical middle (int(height / 2))

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  bool operator==(const Point2&) const = default;
};

// One point of a pen trace. `pen` is the pen state on the way INTO this point: true means the segment from
// the previous point to this one is ink; false means the pen moved lifted (a pen-up move). A zero-length
// inked segment is a dot. The pen flag of the first point of a trace has no segment and is ignored.
struct TracePoint {
  double x = 0.0;
  double y = 0.0;
  bool pen = true;
  bool operator==(const TracePoint&) const = default;
};

}  // namespace sc::writing
