#include "engine/parking/parking_lot.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/core/rng.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

Pose spot_pose(int spot) {
  using namespace parking;
  if (spot < 0 || spot >= kSpotCount) throw std::out_of_range("spot_pose: spot " + std::to_string(spot));
  const int column = spot % kSpotsPerRow;
  const double side = spot < kSpotsPerRow ? 1.0 : -1.0;
  const double x = kSpotWidth * (column - 7) - 2.0;
  return Pose{x, side * (kRowOffset + kSpotLength / 2), side * std::numbers::pi / 2};
}

std::vector<LineSegment> spot_lines(int spot) {
  using namespace parking;
  const Pose centre = spot_pose(spot);
  const double side = centre.y > 0 ? 1.0 : -1.0;
  const double y0 = side * kRowOffset;
  const double y1 = side * (kRowOffset + kSpotLength);
  const double half = kSpotWidth / 2;
  return {{centre.x - half, y0, centre.x - half, y1}, {centre.x + half, y0, centre.x + half, y1}};
}

ParkingLayout make_parked_layout(std::uint64_t obstacle_seed, int free_spot) {
  using namespace parking;
  ParkingLayout layout;
  Rng rng(obstacle_seed);
  for (int spot = 0; spot < kSpotCount; ++spot) {
    // Always draw the same number of values per spot so each spot's car does not depend on the others.
    const double occupied = rng.uniform();
    const double flip = rng.uniform();
    const double lateral = rng.uniform(-0.4, 0.4);
    const double along = rng.uniform(-0.6, 0.6);
    const double yaw = rng.uniform(-0.06, 0.06);
    if (spot == free_spot || occupied >= 0.6) continue;
    const Pose centre = spot_pose(spot);
    // The spot axis is vertical, so "lateral" is x and "along" is y.
    OrientedBox car{centre.x + lateral, centre.y + along, centre.heading + yaw, kCarLength / 2, kCarWidth / 2};
    if (flip < 0.5) car.heading += std::numbers::pi;
    layout.parked_cars.push_back(car);
  }
  const double half_t = kWallThickness / 2;
  const double cx = (kWallInnerMinX + kWallInnerMaxX) / 2;
  const double half_x = (kWallInnerMaxX - kWallInnerMinX) / 2 + kWallThickness;  // closes the corners
  const double half_y = kWallInnerY + kWallThickness;
  layout.walls = {
      {cx, kWallInnerY + half_t, 0.0, half_x, half_t},
      {cx, -kWallInnerY - half_t, 0.0, half_x, half_t},
      {kWallInnerMinX - half_t, 0.0, 0.0, half_t, half_y},
      {kWallInnerMaxX + half_t, 0.0, 0.0, half_t, half_y},
  };
  return layout;
}

}  // namespace sc
