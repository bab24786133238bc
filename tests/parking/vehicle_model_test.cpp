// The bicycle sub-step against cases derived by hand from reference-facts §1.5.
#include "engine/parking/vehicle_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

namespace sc {
namespace {

constexpr double kDt = 1.0 / 15.0;

TEST(VehicleModel, ClipsActionsAndMapsThemToPhysicalControls) {
  const ParkingAction u = clip_action({2.0, -3.0});
  EXPECT_EQ(u[0], 1.0);
  EXPECT_EQ(u[1], -1.0);
  EXPECT_DOUBLE_EQ(acceleration_of(u), 5.0);
  EXPECT_DOUBLE_EQ(steering_of(u), -std::numbers::pi / 4);
  const ParkingAction n = clip_action({std::numeric_limits<double>::quiet_NaN(), 0.25});
  EXPECT_EQ(n[0], 0.0);
  EXPECT_EQ(n[1], 0.25);
}

TEST(VehicleModel, PositionUsesTheOldSpeedAndSpeedIntegratesLast) {
  // From rest, the first sub-step cannot move the car; three sub-steps at a = 5 travel (0 + 1/3 + 2/3)/15.
  VehicleState s{0.0, 0.0, 0.0, 0.0};
  s = bicycle_substep(s, 5.0, 0.0);
  EXPECT_EQ(s.x, 0.0);
  EXPECT_DOUBLE_EQ(s.speed, 5.0 * kDt);
  s = bicycle_substep(s, 5.0, 0.0);
  s = bicycle_substep(s, 5.0, 0.0);
  EXPECT_NEAR(s.x, 1.0 / 15.0, 1e-15);
  EXPECT_EQ(s.y, 0.0);
  EXPECT_NEAR(s.speed, 1.0, 1e-15);
}

TEST(VehicleModel, FullLockTurnsWithTheSlipAngle) {
  // delta = pi/4: tan = 1, beta = atan(1/2); heading rate = v sin(beta) / 2.5.
  const VehicleState s{1.0, 2.0, 0.3, 6.0};
  const VehicleState n = bicycle_substep(s, 0.0, std::numbers::pi / 4);
  const double beta = std::atan(0.5);
  EXPECT_NEAR(n.x, 1.0 + 6.0 * std::cos(0.3 + beta) * kDt, 1e-14);
  EXPECT_NEAR(n.y, 2.0 + 6.0 * std::sin(0.3 + beta) * kDt, 1e-14);
  EXPECT_NEAR(n.heading, 0.3 + 6.0 * std::sin(beta) / 2.5 * kDt, 1e-14);
  EXPECT_EQ(n.speed, 6.0);
}

TEST(VehicleModel, ReversingWithRightLockTurnsLeft) {
  const VehicleState n = bicycle_substep({0.0, 0.0, 0.0, -3.0}, 0.0, -std::numbers::pi / 4);
  EXPECT_GT(n.heading, 0.0);  // negative speed and negative beta: heading increases
  EXPECT_LT(n.x, 0.0);
}

TEST(VehicleModel, HeadingIsNeverWrapped) {
  VehicleState s{0.0, 0.0, 0.0, 10.0};
  for (int i = 0; i < 60; ++i) s = bicycle_substep(s, 0.0, std::numbers::pi / 4);
  EXPECT_GT(s.heading, 2.0 * std::numbers::pi);
}

TEST(VehicleModel, ForwardSpeedGuardCapsAcceleration) {
  // The guard acts only once v > 40, so the speed can overshoot 40 by up to one sub-step of acceleration.
  const VehicleState n = bicycle_substep({0.0, 0.0, 0.0, 39.9}, 5.0, 0.0);
  EXPECT_NEAR(n.speed, 39.9 + 5.0 * kDt, 1e-12);
  const VehicleState over = bicycle_substep({0.0, 0.0, 0.0, 40.5}, 5.0, 0.0);
  EXPECT_NEAR(over.speed, 40.5 - 0.5 * kDt, 1e-12);  // a <- min(5, -0.5)
}

TEST(VehicleModel, ReverseSpeedGuardKeepsTheUpstreamBug) {
  // Upstream uses a <- max(a, 40 - v) for v < -40, i.e. +80.5 m/s^2 here (kept for fidelity).
  const VehicleState n = bicycle_substep({0.0, 0.0, 0.0, -40.5}, -5.0, 0.0);
  EXPECT_NEAR(n.speed, -40.5 + 80.5 * kDt, 1e-12);
}

}  // namespace
}  // namespace sc
