#pragma once
// Plain geometry of the writing canvas, without GL (unit-tested directly): the camera that shows the
// 500 x 300 px canvas (world units = canvas pixels, y down, reference-facts §2.5), and the split of a pen
// trace into what is drawn - ink runs, dots, pen-up hops - and the direction marks along a ghost path.
#include <span>
#include <vector>

#include "engine/render/camera2d.hpp"
#include "engine/writing/trace_point.hpp"

namespace sc::writing_view {

inline constexpr float kCanvasMargin = 12.0f;  // canvas pixels of desk shown around the paper

// The canvas plus `margin` on every side, fitted (aspect kept, centred) into `viewport`.
Camera2D writing_canvas_camera(PixelViewport viewport, float margin = kCanvasMargin);
WorldRect canvas_rect();

// What a trace looks like. A trace point's pen flag says how the pen arrived there (trace_point.hpp).
struct InkPaths {
  std::vector<std::vector<Vec2f>> runs;  // maximal chains of inked segments of non-zero length
  std::vector<Vec2f> dots;               // inked chains that never move (a tap)
  std::vector<std::vector<Vec2f>> hops;  // maximal chains of pen-up moves (the lifted pen's path)
};
InkPaths split_ink(std::span<const writing::TracePoint> trace);

std::vector<Vec2f> to_vec2f(std::span<const writing::TracePoint> trace);

// A short arrow showing which way a path goes at one place.
struct DirectionMark {
  Vec2f from;
  Vec2f to;
};
// Marks every `spacing` of arc length along `path`, the first at spacing / 2 (none on a path shorter than
// that). Each mark is `length` long, centred on the path, pointing along the chord from `window` before to
// `window` after the mark: the paths are infilled in <= 1 px steps, so a single step's direction is jittery.
std::vector<DirectionMark> direction_marks(std::span<const Vec2f> path, float spacing, float length,
                                           float window = 4.0f);

// Arc length of a polyline.
float path_length(std::span<const Vec2f> path);
// The point at arc length `s` (clamped to the path's ends); an empty path gives (0, 0).
Vec2f point_at_length(std::span<const Vec2f> path, float s);

}  // namespace sc::writing_view
