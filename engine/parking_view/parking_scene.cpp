#include "engine/parking_view/parking_scene.hpp"

#include <cmath>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/parking_view/lot_painter.hpp"
#include "engine/parking_view/parking_camera.hpp"
#include "engine/parking_view/teaching_overlays.hpp"

namespace sc {
namespace {

// The car's footprint (its bounding circle's box is enough to keep it inside the view).
void add_car_extent(std::vector<Vec2f>& points, const CarPose& car) {
  const float r = 2.8f;  // half-diagonal of 5x2 m plus the tyres
  points.push_back({car.center.x - r, car.center.y - r});
  points.push_back({car.center.x + r, car.center.y + r});
}

}  // namespace

Camera2D parking_scene_camera(const ParkingSceneView& view, CameraMode mode, PixelViewport viewport) {
  if (view.layout == nullptr) throw InputError("parking scene", "no lot layout given");
  if (mode == CameraMode::follow_car) return follow_car_camera(view.car ? view.car->center : Vec2f{}, viewport);
  std::vector<Vec2f> points(view.trail.begin(), view.trail.end());
  if (view.car) add_car_extent(points, *view.car);
  if (view.ghost_path != nullptr)
    for (const PathSample& s : view.ghost_path->samples) add_car_extent(points, car_pose_of(s.vehicle, 0.0));
  return whole_lot_camera(*view.layout, points, viewport);
}

void paint_parking_scene(Renderer2D& r, const ParkingSceneView& view) {
  if (view.layout == nullptr) throw InputError("parking scene", "no lot layout given");
  paint_lot(r, *view.layout);
  if (view.ghost_path != nullptr) paint_ghost_path(r, *view.ghost_path);
  paint_goal(r, view.goal, view.reverse_in);
  paint_trail(r, view.trail);
  if (view.ghost_path != nullptr && view.ghost_time)
    paint_ghost_car(r, *view.ghost_path, *view.ghost_time, view.ghost_alpha);
  if (view.car) paint_car(r, *view.car, reference_car_look());
}

}  // namespace sc
