#pragma once
// Geometry shared by the physical gamepad stick and the on-screen virtual joystick: dead zones that rescale
// (so the output starts from 0 at the dead-zone edge instead of jumping), and a direction-preserving map
// between the unit disc a round stick can reach and the square action space [-1,1]^2.
//
// Why the disc->square map: a round stick clamped to its circle can only reach |u| <= 1 in Euclidean norm,
// so (full throttle, full lock) would be unreachable, and an expert action such as (0.98, -0.69) (the
// golden episode's first step) could not be shown on the stick. Stretching each ray by |d|_2/|d|_inf keeps
// the direction of the push and makes the rim of the disc the border of the square, both ways exactly.
namespace sc::input {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

double length(Vec2 v);

// 1-D dead zone: |v| <= dead_zone -> 0, else sign(v)·(|v| - dead_zone)/(1 - dead_zone), clamped to [-1, 1].
// Requires 0 <= dead_zone < 1.
double rescale_axial_dead_zone(double v, double dead_zone);

// Radial dead zone on a 2-D stick: inside the circle of radius dead_zone -> (0,0); outside, the magnitude is
// rescaled the same way as the 1-D case and capped at 1, the direction is kept. Continuous everywhere.
Vec2 rescale_radial_dead_zone(Vec2 v, double dead_zone);

// Scales v down onto the unit circle when it lies outside (square-gated sticks report corners near (1,1)).
Vec2 clamp_to_unit_disc(Vec2 v);

// Unit disc -> square [-1,1]^2 along rays (d·|d|_2/|d|_inf), and its inverse (s·|s|_inf/|s|_2).
Vec2 disc_to_square(Vec2 d);
Vec2 square_to_disc(Vec2 s);

}  // namespace sc::input
