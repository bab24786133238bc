#include "engine/parking_view/lot_painter.hpp"

#include <array>
#include <cmath>
#include <string>

#include "engine/parking/vehicle_model.hpp"
#include "engine/parking_view/car_painter.hpp"
#include "engine/render/world_label.hpp"

namespace sc {
namespace {

Vec2f to_vec(double x, double y) { return {static_cast<float>(x), static_cast<float>(y)}; }

RotatedRect box_rect(const OrientedBox& box) {
  return {to_vec(box.x, box.y), to_vec(box.half_length, box.half_width), static_cast<float>(box.heading)};
}

void paint_walls(Renderer2D& r, const ParkingLayout& layout) {
  for (const OrientedBox& wall : layout.walls) {
    r.fill_rect(box_rect(wall), parking_view::kWall);
    r.outline_rect(box_rect(wall), Stroke::world(0.12f), parking_view::kWallEdge);
  }
}

}  // namespace

void paint_lot(Renderer2D& r, const ParkingLayout& layout) {
  r.begin_static_layer();  // the lot never moves: copied from a cache while the camera stays put
  const WorldRect visible = r.camera().visible_world();
  r.fill_rect({{(visible.min_x + visible.max_x) / 2, (visible.min_y + visible.max_y) / 2},
               {(visible.max_x - visible.min_x) / 2, (visible.max_y - visible.min_y) / 2},
               0.0f},
              parking_view::kGround);
  for (int spot = 0; spot < parking::kSpotCount; ++spot)
    for (const LineSegment& line : spot_lines(spot)) {
      const std::array<Vec2f, 2> points{to_vec(line.x0, line.y0), to_vec(line.x1, line.y1)};
      r.polyline(points, Stroke::world(parking_view::kLaneLineWidth), parking_view::kLaneLine);
    }
  paint_walls(r, layout);
  const CarLook parked = parked_car_look();
  for (const OrientedBox& car : layout.parked_cars)
    paint_car(r, {to_vec(car.x, car.y), static_cast<float>(car.heading), 0.0f}, parked);
  r.end_static_layer();
}

void paint_goal(Renderer2D& r, const Pose& goal, bool reverse_in) {
  const Vec2f c = to_vec(goal.x, goal.y);
  const float h = static_cast<float>(goal.heading);
  const Vec2f forward{std::cos(h), std::sin(h)};
  const Color target = reverse_in ? parking_view::kReverseGoal : parking_view::kGoalFill;
  // Target car: a translucent footprint, a dashed outline and a solid front edge with an arrow toward it.
  const RotatedRect car{c, {static_cast<float>(parking::kHalfLength), static_cast<float>(parking::kCarWidth / 2)}, h};
  r.fill_rect(car, target.with_alpha(0.16f));
  const Vec2f side{-forward.y, forward.x};
  const Vec2f half_l = forward * car.half_size.x, half_w = side * car.half_size.y;
  const std::array<Vec2f, 4> corners{c - half_l - half_w, c + half_l - half_w, c + half_l + half_w,
                                     c - half_l + half_w};
  PathStyle closed;
  closed.closed = true;
  r.dashed_polyline(corners, Stroke::world(0.16f), {0.5f, 0.35f}, target.with_alpha(0.95f), closed);
  const std::array<Vec2f, 2> front{corners[1], corners[2]};
  r.polyline(front, Stroke::world(0.35f), target);
  // The reference landmark: 2x2 m light-blue square with a dark 1 px (1/7 m) outline, on the goal point.
  const RotatedRect square{c, {1.0f, 1.0f}, h};
  r.fill_rect(square, parking_view::kGoalFill);
  r.outline_rect(square, Stroke::world(1.0f / 7.0f), parking_view::kGoalOutline);
  r.arrow(c + forward * 1.2f, c + forward * 2.3f, Stroke::world(0.22f), {0.75f, 0.9f}, target);
}

void label_spots(const Camera2D& camera, ImDrawList* draw_list) {
  LabelStyle style;
  style.color = Color::hex(0xffffff, 0.85f);
  style.background = Color::hex(0x000000, 0.35f);
  for (int spot = 0; spot < parking::kSpotCount; ++spot) {
    const Pose p = spot_pose(spot);
    // Just outside the spot entrance, in the aisle.
    const float y = static_cast<float>(p.y > 0 ? parking::kRowOffset - 1.0 : -parking::kRowOffset + 1.0);
    draw_world_label(camera, {static_cast<float>(p.x), y}, std::to_string(spot), style, draw_list);
  }
}

}  // namespace sc
