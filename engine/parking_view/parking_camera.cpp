#include "engine/parking_view/parking_camera.hpp"

#include <algorithm>
#include <cmath>

namespace sc {

WorldRect lot_bounds(const ParkingLayout& layout) {
  using namespace parking;
  const float half_spot = static_cast<float>(kSpotWidth / 2);
  const float min_x = static_cast<float>(spot_pose(0).x) - half_spot;
  const float max_x = static_cast<float>(spot_pose(kSpotsPerRow - 1).x) + half_spot;
  const float max_y = static_cast<float>(kRowOffset + kSpotLength);
  WorldRect bounds{min_x, -max_y, max_x, max_y};
  for (const OrientedBox& wall : layout.walls) {
    const double c = std::fabs(std::cos(wall.heading)), s = std::fabs(std::sin(wall.heading));
    const float hx = static_cast<float>(c * wall.half_length + s * wall.half_width);
    const float hy = static_cast<float>(s * wall.half_length + c * wall.half_width);
    const float x = static_cast<float>(wall.x), y = static_cast<float>(wall.y);
    bounds = {std::min(bounds.min_x, x - hx), std::min(bounds.min_y, y - hy), std::max(bounds.max_x, x + hx),
              std::max(bounds.max_y, y + hy)};
  }
  return bounds;
}

WorldRect include_points(WorldRect b, std::span<const Vec2f> points) {
  for (const Vec2f& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    b = {std::min(b.min_x, p.x), std::min(b.min_y, p.y), std::max(b.max_x, p.x), std::max(b.max_y, p.y)};
  }
  return b;
}

WorldRect grow(WorldRect b, float margin) {
  return {b.min_x - margin, b.min_y - margin, b.max_x + margin, b.max_y + margin};
}

Camera2D whole_lot_camera(const ParkingLayout& layout, std::span<const Vec2f> extra_points, PixelViewport viewport) {
  const WorldRect bounds = grow(include_points(lot_bounds(layout), extra_points), parking_view::kLotMargin);
  return Camera2D(bounds, viewport, WorldYAxis::down);
}

Camera2D follow_car_camera(Vec2f car, PixelViewport viewport) {
  const float hw = parking_view::kFollowViewWidth / 2, hh = parking_view::kFollowViewHeight / 2;
  const Vec2f c{std::isfinite(car.x) ? car.x : 0.0f, std::isfinite(car.y) ? car.y : 0.0f};
  return Camera2D({c.x - hw, c.y - hh, c.x + hw, c.y + hh}, viewport, WorldYAxis::down);
}

}  // namespace sc
