#pragma once
// Lot geometry of the reference Parking environment (reference-facts §1.2) and the obstacles of our
// "parked" variant (parked cars in other spots, walls around the lot).
#include <cstdint>
#include <vector>

namespace sc {

namespace parking {
inline constexpr int kSpotsPerRow = 15;
inline constexpr int kSpotCount = 2 * kSpotsPerRow;  // 30
inline constexpr double kSpotWidth = 4.0;            // m (lane width)
inline constexpr double kSpotLength = 8.0;           // m
inline constexpr double kRowOffset = 10.0;           // m from the centre line to the spot entrance
// Walls of the "parked" variant: inner faces 2 m behind the spot ends and 4 m beyond the outermost
// spot edges (x from -32 to 28), 1 m thick. The classic lot is unbounded, like the reference.
inline constexpr double kWallInnerMinX = -36.0;
inline constexpr double kWallInnerMaxX = 32.0;
inline constexpr double kWallInnerY = 20.0;
inline constexpr double kWallThickness = 1.0;
}  // namespace parking

struct Pose {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;
};

// A rectangle centred at (x, y), its length along `heading`.
struct OrientedBox {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;
  double half_length = 0.0;
  double half_width = 0.0;
};

// Spot k in 0..29 in the reference's order: 0..14 are the "a->b" spots entered towards +y (centres at
// y = +14, heading +pi/2), 15..29 the "b->c" spots entered towards -y (y = -14, heading -pi/2); within a
// row, x = 4*(k mod 15 - 7) - 2. The pose is the spot centre (the goal point), heading pointing in.
Pose spot_pose(int spot);
// The lane lines of one spot: the two long sides, as segments (x0, y0, x1, y1), for rendering.
struct LineSegment {
  double x0, y0, x1, y1;
};
std::vector<LineSegment> spot_lines(int spot);

struct ParkingLayout {
  std::vector<OrientedBox> parked_cars;
  std::vector<OrientedBox> walls;
  bool empty() const { return parked_cars.empty() && walls.empty(); }
};

// Parked cars for the "parked" variant, drawn from `obstacle_seed`: every spot except `free_spot` is
// occupied with probability 0.6 by a 5x2 m car, nose in or out, jittered inside its spot (lateral
// +-0.4 m, longitudinal +-0.6 m, heading +-0.06 rad) so it never crosses the spot lines. Nothing is ever
// placed in the aisle (|y| < 10), so the goal spot can always be entered straight from the aisle with at
// least 4.9 m of free width. Includes the four walls.
ParkingLayout make_parked_layout(std::uint64_t obstacle_seed, int free_spot);

}  // namespace sc
