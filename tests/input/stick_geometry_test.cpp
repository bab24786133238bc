#include "engine/input/stick_geometry.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace sc::input {
namespace {

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

TEST(AxialDeadZone, ZeroInsideAndRescaledOutside) {
  EXPECT_EQ(rescale_axial_dead_zone(0.1, 0.2), 0.0);
  EXPECT_EQ(rescale_axial_dead_zone(-0.2, 0.2), 0.0);
  EXPECT_DOUBLE_EQ(rescale_axial_dead_zone(0.6, 0.2), 0.5);
  EXPECT_DOUBLE_EQ(rescale_axial_dead_zone(-0.6, 0.2), -0.5);
  EXPECT_EQ(rescale_axial_dead_zone(1.0, 0.2), 1.0);
  EXPECT_EQ(rescale_axial_dead_zone(-1.0, 0.2), -1.0);
}

TEST(AxialDeadZone, ContinuousAtTheEdge) {
  // Without rescaling the output would jump from 0 to 0.2 when leaving the dead zone.
  EXPECT_NEAR(rescale_axial_dead_zone(0.2 + 1e-9, 0.2), 1e-9 / 0.8, 1e-15);
}

TEST(RadialDeadZone, ZeroInsideTheCircleInEveryDirection) {
  for (int i = 0; i < 36; ++i) {
    const Vec2 d = direction(i * std::numbers::pi / 18);
    EXPECT_EQ(rescale_radial_dead_zone({0.1499 * d.x, 0.1499 * d.y}, 0.15), Vec2{}) << i;
  }
}

TEST(RadialDeadZone, ContinuousAtTheEdgeAndFullAtTheRim) {
  for (int i = 0; i < 36; ++i) {
    const double angle = i * std::numbers::pi / 18;
    const Vec2 d = direction(angle);
    const Vec2 just_out = rescale_radial_dead_zone({(0.15 + 1e-9) * d.x, (0.15 + 1e-9) * d.y}, 0.15);
    EXPECT_NEAR(length(just_out), 1e-9 / 0.85, 1e-14) << i;
    const Vec2 full = rescale_radial_dead_zone(d, 0.15);
    EXPECT_NEAR(length(full), 1.0, 1e-15) << i;
    EXPECT_NEAR(std::atan2(full.y, full.x), std::atan2(d.y, d.x), 1e-12) << "direction kept " << i;
  }
}

TEST(RadialDeadZone, SquareGateCornerIsCappedAtFullDeflection) {
  const Vec2 corner = rescale_radial_dead_zone({1.0, -1.0}, 0.1);
  EXPECT_NEAR(length(corner), 1.0, 1e-15);
  EXPECT_NEAR(corner.x, -corner.y, 1e-15);
}

TEST(DiscToSquare, AxesUnchangedAndDiagonalStretchedToTheCorner) {
  EXPECT_EQ(disc_to_square({0.0, 0.5}), (Vec2{0.0, 0.5}));
  EXPECT_EQ(disc_to_square({-0.3, 0.0}), (Vec2{-0.3, 0.0}));
  EXPECT_EQ(disc_to_square({}), Vec2{});
  const Vec2 corner = disc_to_square({std::sqrt(0.5), -std::sqrt(0.5)});
  EXPECT_NEAR(corner.x, 1.0, 1e-15);
  EXPECT_NEAR(corner.y, -1.0, 1e-15);
}

TEST(DiscToSquare, RimMapsOntoTheSquareBorderAndBack) {
  for (int i = 0; i < 360; ++i) {
    const Vec2 rim = direction(i * std::numbers::pi / 180);
    const Vec2 s = disc_to_square(rim);
    EXPECT_NEAR(std::max(std::abs(s.x), std::abs(s.y)), 1.0, 1e-15) << i;
    const Vec2 back = square_to_disc(s);
    EXPECT_NEAR(back.x, rim.x, 1e-15) << i;
    EXPECT_NEAR(back.y, rim.y, 1e-15) << i;
  }
}

TEST(DiscToSquare, InteriorRoundTrip) {
  for (double x = -1.0; x <= 1.0; x += 0.125)
    for (double y = -1.0; y <= 1.0; y += 0.125) {
      const Vec2 d = square_to_disc({x, y});
      EXPECT_LE(length(d), 1.0 + 1e-15);
      const Vec2 s = disc_to_square(d);
      EXPECT_NEAR(s.x, x, 1e-15);
      EXPECT_NEAR(s.y, y, 1e-15);
    }
}

TEST(ClampToUnitDisc, OnlyShrinksPointsOutside) {
  EXPECT_EQ(clamp_to_unit_disc({0.3, 0.4}), (Vec2{0.3, 0.4}));
  const Vec2 c = clamp_to_unit_disc({3.0, 4.0});
  EXPECT_DOUBLE_EQ(c.x, 0.6);
  EXPECT_DOUBLE_EQ(c.y, 0.8);
}

}  // namespace
}  // namespace sc::input
