// Cameras: the whole-lot view contains the lot (and walls, and a far-away car) with a margin and keeps the
// aspect; the follow view is the reference's 85.7 m x 42.9 m centred on the car.
#include "engine/parking_view/parking_camera.hpp"

#include <array>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace sc {
namespace {

void expect_inside(const Camera2D& camera, Vec2f world) {
  const Vec2f p = camera.world_to_pixel(world);
  const PixelViewport& v = camera.viewport();
  EXPECT_GE(p.x, v.x) << world.x << "," << world.y;
  EXPECT_LE(p.x, v.x + v.width);
  EXPECT_GE(p.y, v.y);
  EXPECT_LE(p.y, v.y + v.height);
}

TEST(ParkingCamera, ClassicLotBoundsAreTheSpotLines) {
  const WorldRect b = lot_bounds(ParkingLayout{});
  EXPECT_FLOAT_EQ(b.min_x, -32.0f);  // the reference lot is not centred on x = 0
  EXPECT_FLOAT_EQ(b.max_x, 28.0f);
  EXPECT_FLOAT_EQ(b.min_y, -18.0f);
  EXPECT_FLOAT_EQ(b.max_y, 18.0f);
}

TEST(ParkingCamera, ParkedLotBoundsIncludeTheWalls) {
  const WorldRect b = lot_bounds(make_parked_layout(3, 0));
  EXPECT_FLOAT_EQ(b.min_x, -37.0f);
  EXPECT_FLOAT_EQ(b.max_x, 33.0f);
  EXPECT_FLOAT_EQ(b.min_y, -21.0f);
  EXPECT_FLOAT_EQ(b.max_y, 21.0f);
}

TEST(ParkingCamera, WholeLotViewFitsLotAndCarWithMargin) {
  const std::array<Vec2f, 1> car{Vec2f{60.0f, -5.0f}};  // the car drove off the lot
  const Camera2D camera = whole_lot_camera(ParkingLayout{}, car, {100, 0, 1180, 720});
  for (Vec2f corner : {Vec2f{-32 - 3, -18 - 3}, Vec2f{60 + 3, 18 + 3}, Vec2f{60, -5}}) expect_inside(camera, corner);
  // Aspect kept: one metre is as many pixels horizontally as vertically (a single scale).
  const Vec2f a = camera.world_to_pixel({0, 0}), b = camera.world_to_pixel({1, 1});
  EXPECT_NEAR(b.x - a.x, b.y - a.y, 1e-3f);
  // Width-limited here (98 m wide x 42 m tall in 1180x720): the width is used fully.
  EXPECT_NEAR(camera.pixels_per_unit(), 1180.0f / (63.0f + 35.0f), 1e-3f);
}

TEST(ParkingCamera, NonFinitePointsAreSkipped) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::array<Vec2f, 2> points{Vec2f{nan, 0}, Vec2f{0, std::numeric_limits<float>::infinity()}};
  const WorldRect b = include_points(lot_bounds(ParkingLayout{}), points);
  EXPECT_FLOAT_EQ(b.max_y, 18.0f);
  EXPECT_FLOAT_EQ(b.min_x, -32.0f);
}

TEST(ParkingCamera, FollowViewIsTheReferenceViewCentredOnTheCar) {
  const Camera2D camera = follow_car_camera({10, -4}, {0, 0, 600, 300});
  EXPECT_NEAR(camera.pixels_per_unit(), 7.0f, 1e-4f);  // 600x300 px: exactly the reference's 7 px/m
  const Vec2f centre = camera.world_to_pixel({10, -4});
  EXPECT_NEAR(centre.x, 300.0f, 1e-3f);
  EXPECT_NEAR(centre.y, 150.0f, 1e-3f);
  // y down, like pygame: a point 1 m further in +y is lower on screen.
  EXPECT_GT(camera.world_to_pixel({10, -3}).y, centre.y);
}

}  // namespace
}  // namespace sc
