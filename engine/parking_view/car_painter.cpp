#include "engine/parking_view/car_painter.hpp"

#include <algorithm>
#include <cmath>

#include "engine/parking/vehicle_model.hpp"

namespace sc {
namespace {

// Car geometry of reference-facts §1.9 in metres, in the car frame: u from the rear bumper (0) to the front
// bumper (5), w lateral from the centre line. The reference's headlight and roof spans are slightly
// asymmetric (w -0.933..-0.333 and +0.24..+0.84; roof -0.776..+0.724) only because pygame truncates to
// whole pixels at 7 px/m; we draw them symmetric with the same sizes and mean offsets.
constexpr float kLength = static_cast<float>(parking::kCarLength);
constexpr float kWidth = static_cast<float>(parking::kCarWidth);
constexpr float kHeadlightFrontU = 5.0f, kHeadlightLength = 0.72f;
constexpr float kHeadlightInnerW = 0.287f, kHeadlightWidth = 0.6f;
constexpr float kRoofRearU = 1.0f, kRoofLength = 2.0f, kRoofHalfWidth = 0.75f;
constexpr float kRingU = 4.03f;
constexpr float kRingRadius = 4.0f / 7.0f;     // 4 px at 7 px/m
constexpr float kRingThickness = 2.0f / 7.0f;  // 2 px
constexpr float kOutlineWidth = 1.0f / 7.0f;   // 1 px
constexpr float kTyreLength = 1.0f, kTyreWidth = 0.3f;

Color channel_scaled(Color c, float factor, float alpha) {
  return {std::min(1.0f, c.r * factor), std::min(1.0f, c.g * factor), std::min(1.0f, c.b * factor), alpha};
}

// Car frame (u from the rear bumper, w lateral) -> world.
struct CarFrame {
  Vec2f center;
  Vec2f forward;  // unit vector along the heading
  Vec2f side;     // unit vector toward +w (the driver's right on the y-down lot)
  Vec2f at(float u, float w) const { return center + forward * (u - kLength / 2) + side * w; }
};

RotatedRect car_rect(const CarFrame& frame, float heading, float u0, float u1, float w0, float w1) {
  return {frame.at((u0 + u1) / 2, (w0 + w1) / 2), {(u1 - u0) / 2, (w1 - w0) / 2}, heading};
}

}  // namespace

CarLook car_look_from_body(Color body, float alpha) {
  CarLook look;
  look.body = body.with_alpha(alpha);
  look.headlight = channel_scaled(body, 1.0f / 0.68f, alpha);
  look.roof = channel_scaled(body, 0.83f, alpha);
  look.outline = Color::hex(0x464646, alpha);  // (70,70,70)
  look.ring = Color::hex(0x24253b, alpha);     // (36,37,59)
  look.tyre = Color::hex(0x464646, alpha);
  return look;
}

CarLook reference_car_look() {
  CarLook look = car_look_from_body(Color::hex(0xebbd34));  // (235,189,52)
  // Exactly the reference's truncated values: (255,255,76) and (195,156,43).
  look.headlight = Color::hex(0xffff4c);
  look.roof = Color::hex(0xc39c2b);
  return look;
}

CarLook parked_car_look() { return car_look_from_body(Color::hex(0x4a6f9e)); }

CarLook ghost_car_look(float alpha) {
  CarLook look = car_look_from_body(Color::hex(0xbfe9ff), alpha);
  look.outline = Color::hex(0xe8f7ff, alpha);
  look.ring = Color::hex(0x1d3a5c, alpha);
  look.tyre = Color::hex(0x2c4a66, alpha);
  return look;
}

void paint_car(Renderer2D& r, const CarPose& pose, const CarLook& look) {
  const Vec2f forward{std::cos(pose.heading), std::sin(pose.heading)};
  const CarFrame f{pose.center, forward, {-forward.y, forward.x}};
  const float h = pose.heading;
  r.fill_rect(car_rect(f, h, 0, kLength, -kWidth / 2, kWidth / 2), look.body);
  const float u_rear_light = kHeadlightFrontU - kHeadlightLength;
  for (float sign : {-1.0f, 1.0f}) {
    const float w_inner = sign * kHeadlightInnerW, w_outer = sign * (kHeadlightInnerW + kHeadlightWidth);
    r.fill_rect(car_rect(f, h, u_rear_light, kHeadlightFrontU, std::min(w_inner, w_outer), std::max(w_inner, w_outer)),
                look.headlight);
  }
  r.fill_rect(car_rect(f, h, kRoofRearU, kRoofRearU + kRoofLength, -kRoofHalfWidth, kRoofHalfWidth), look.roof);
  r.outline_rect(car_rect(f, h, 0, kLength, -kWidth / 2, kWidth / 2), Stroke::world(kOutlineWidth), look.outline);
  r.outline_circle(f.at(kRingU, 0), kRingRadius - kRingThickness / 2, Stroke::world(kRingThickness), look.ring);
  for (float u : {0.0f, kLength})
    for (float w : {-kWidth / 2, kWidth / 2}) {
      const float angle = u > 0 ? h + pose.steering : h;
      r.fill_rect({f.at(u, w), {kTyreLength / 2, kTyreWidth / 2}, angle}, look.tyre);
    }
}

}  // namespace sc
