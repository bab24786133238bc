#pragma once
// Car-versus-lot collision test with Box2D 2.4 polygons (b2TestOverlap), built once per layout so that
// the per-step query allocates nothing.
#include <vector>

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include "engine/parking/parking_lot.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

class CollisionChecker {
 public:
  explicit CollisionChecker(const ParkingLayout& layout);

  // True when the 5x2 m car body at `state` overlaps a parked car or a wall (touching counts).
  bool car_collides(const VehicleState& state) const;
  bool has_obstacles() const { return !obstacles_.empty(); }

 private:
  struct Obstacle {
    b2PolygonShape shape;
    b2Transform transform;
    double min_x, max_x, min_y, max_y;  // axis-aligned bounds for the cheap rejection test
  };
  std::vector<Obstacle> obstacles_;
  b2PolygonShape car_shape_;
};

}  // namespace sc
