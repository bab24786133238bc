#pragma once
// Tessellation of 2D primitives into convex pieces with their outline marked (engine/render/convex_pieces.hpp),
// from which the renderer makes feathered triangles. Pure geometry with no GL, so it is unit-tested directly.
// Widths and tolerances are in the same units as the points.
#include <span>
#include <vector>

#include "engine/render/convex_pieces.hpp"
#include "engine/render/draw_types.hpp"

namespace sc {

// A polyline of the given width with joins and caps. Consecutive duplicate points are ignored; fewer than two
// distinct points draws nothing (a round cap draws a dot for a single point).
// `max_chord_error` bounds how far round joins/caps deviate from a true circle.
void append_polyline(ConvexPieces& out, std::span<const Vec2f> points, float width, const PathStyle& style,
                     float max_chord_error);

// The "on" pieces of a dash pattern along a polyline; the pattern continues across vertices.
std::vector<std::vector<Vec2f>> dash_polyline(std::span<const Vec2f> points, float dash_length, float gap_length);

void append_convex_polygon(ConvexPieces& out, std::span<const Vec2f> corners);
void append_circle(ConvexPieces& out, Vec2f center, float radius, float max_chord_error);
void append_ring(ConvexPieces& out, Vec2f center, float radius, float width, float max_chord_error);
// The 4 corners of a rotated rectangle, counter-clockwise in world axes.
std::vector<Vec2f> rect_corners(const RotatedRect& rect);
// Shaft ending where the head begins, plus a triangular head whose tip is exactly at `to`.
void append_arrow(ConvexPieces& out, Vec2f from, Vec2f to, float width, float head_length, float head_width);

// Segments for a circle of `radius` so that the chord error stays under `max_chord_error` (12..256).
int circle_segments(float radius, float max_chord_error);

}  // namespace sc
