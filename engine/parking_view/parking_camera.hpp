#pragma once
// Cameras of the parking view. The default shows the whole lot (and the car, wherever it went) with a margin,
// aspect kept; the follow camera is the reference's view (reference-facts §1.9): 600x300 px at 7 px/m,
// i.e. 85.7 m x 42.9 m centred on the car, fitted to the viewport.
#include <span>

#include "engine/parking/parking_lot.hpp"
#include "engine/render/camera2d.hpp"

namespace sc {

namespace parking_view {
inline constexpr float kLotMargin = 3.0f;                 // metres around the lot in the whole-lot view
inline constexpr float kFollowViewWidth = 600.0f / 7.0f;  // metres (reference surface / scaling)
inline constexpr float kFollowViewHeight = 300.0f / 7.0f;
}  // namespace parking_view

// The painted lot: every spot's lines (x -32..28, y -18..18) and the walls when the layout has them.
WorldRect lot_bounds(const ParkingLayout& layout);
// `bounds` grown to include every point (e.g. the car's corners, a path); non-finite points are skipped.
WorldRect include_points(WorldRect bounds, std::span<const Vec2f> points);
WorldRect grow(WorldRect bounds, float margin);

// Whole-lot view: the lot plus `extra_points` (car, paths), with parking_view::kLotMargin around them.
Camera2D whole_lot_camera(const ParkingLayout& layout, std::span<const Vec2f> extra_points, PixelViewport viewport);
// The reference's follow-car view centred on `car`.
Camera2D follow_car_camera(Vec2f car, PixelViewport viewport);

}  // namespace sc
