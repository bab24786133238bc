#include "engine/parking/collision_checker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <box2d/b2_common.h>

namespace sc {
namespace {

// b2TestOverlap treats every polygon as rounded by b2_polygonRadius (0.01 m): shrinking the core box by
// that skin makes the tested shape the true rectangle (only its corners are rounded, by < 0.005 m), so
// two boxes 0.015 m apart no longer "touch" (stack notes §5).
b2PolygonShape box_shape(double half_length, double half_width) {
  b2PolygonShape shape;
  const float skin = b2_polygonRadius;
  shape.SetAsBox(static_cast<float>(half_length) - skin, static_cast<float>(half_width) - skin);
  return shape;
}

// Half extents of a rotated box's axis-aligned bounds.
void half_extents(double heading, double half_length, double half_width, double& ex, double& ey) {
  const double c = std::fabs(std::cos(heading));
  const double s = std::fabs(std::sin(heading));
  ex = c * half_length + s * half_width;
  ey = s * half_length + c * half_width;
}

}  // namespace

CollisionChecker::CollisionChecker(const ParkingLayout& layout)
    : car_shape_(box_shape(parking::kCarLength / 2, parking::kCarWidth / 2)) {
  auto add = [this](const OrientedBox& box) {
    double ex = 0, ey = 0;
    half_extents(box.heading, box.half_length, box.half_width, ex, ey);
    Obstacle o{box_shape(box.half_length, box.half_width),
               b2Transform(b2Vec2(static_cast<float>(box.x), static_cast<float>(box.y)),
                           b2Rot(static_cast<float>(box.heading))),
               box.x - ex,
               box.x + ex,
               box.y - ey,
               box.y + ey};
    obstacles_.push_back(o);
  };
  for (const auto& box : layout.parked_cars) add(box);
  for (const auto& box : layout.walls) add(box);
}

bool CollisionChecker::car_collides(const VehicleState& state) const {
  if (obstacles_.empty()) return false;
  double ex = 0, ey = 0;
  half_extents(state.heading, parking::kCarLength / 2, parking::kCarWidth / 2, ex, ey);
  const b2Transform car(b2Vec2(static_cast<float>(state.x), static_cast<float>(state.y)),
                        b2Rot(static_cast<float>(std::remainder(state.heading, 2.0 * std::numbers::pi))));
  for (const auto& o : obstacles_) {
    if (state.x + ex < o.min_x || state.x - ex > o.max_x || state.y + ey < o.min_y || state.y - ey > o.max_y) continue;
    if (b2TestOverlap(&car_shape_, 0, &o.shape, 0, car, o.transform)) return true;
  }
  return false;
}

}  // namespace sc
