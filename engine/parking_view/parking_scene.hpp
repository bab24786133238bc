#pragma once
// One call that paints a whole parking scene in the right order, for every place that shows the task: the
// free-drive screen, demonstrations and drills of the learner flow, `skillcoach render` and the goldens.
//
//   ParkingSceneView view{.layout = &layout, .goal = goal_pose(scenario), .reverse_in = scenario.reverse_in};
//   view.car = car_pose_of(sim.vehicle(), sim.steering());
//   view.ghost_path = &expert_path;          // optional overlays
//   view.ghost_time = 1.6;
//   renderer.set_camera(parking_scene_camera(view, CameraMode::whole_lot, viewport));
//   paint_parking_scene(renderer, view);
//
// Order (reference-facts §1.9, overlays where the reference draws its target overlay): ground, spot lines,
// walls, parked cars, ghost path, goal, learner's trail, ghost car, car.
#include <optional>
#include <span>

#include "engine/parking/parking_lot.hpp"
#include "engine/parking_view/car_painter.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/render/camera2d.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

struct ParkingSceneView {
  const ParkingLayout* layout = nullptr;  // required: the scenario's lot (make_layout / ParkingSim::layout)
  Pose goal;
  bool reverse_in = false;
  std::optional<CarPose> car;               // the learner's (or replayed) car
  std::span<const Vec2f> trail;             // past positions of `car`
  const ParkingPath* ghost_path = nullptr;  // the expert's path as a ribbon with arrows
  std::optional<double> ghost_time;         // with ghost_path: the ghost car at this time (seconds)
  float ghost_alpha = 0.5f;
};

enum class CameraMode {
  whole_lot,   // the lot, the car, its trail and the ghost path, with a margin (default)
  follow_car,  // the reference's 85.7 m x 42.9 m view centred on the car
};

Camera2D parking_scene_camera(const ParkingSceneView& view, CameraMode mode, PixelViewport viewport);

// Throws InputError when view.layout is null.
void paint_parking_scene(Renderer2D& renderer, const ParkingSceneView& view);

}  // namespace sc
