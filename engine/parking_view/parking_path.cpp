#include "engine/parking_view/parking_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/core/error.hpp"

namespace sc {
namespace {

double shortest_angle_delta(double from, double to) {
  double d = std::fmod(to - from, 2 * std::numbers::pi);
  if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
  if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
  return d;
}

// Records the sub-steps of one control step exactly as ParkingSim::step_substeps computes them (same
// update, same collision rule: the crashed car stops and stays for the rest of the step).
void record_substeps(const std::array<ParkingAction, parking::kSubstepsPerAction>& actions,
                     const CollisionChecker& collisions, ParkingPath& path) {
  VehicleState state = path.samples.back().vehicle;
  double t = path.samples.back().t;
  bool crashed = false;
  for (const ParkingAction& raw : actions) {
    const ParkingAction u = clip_action(raw);
    double steering = steering_of(u);
    if (!crashed) {
      state = bicycle_substep(state, acceleration_of(u), steering);
      if (collisions.has_obstacles() && collisions.car_collides(state)) {
        state.speed = 0.0;
        crashed = true;
      }
    } else {
      steering = 0.0;
    }
    t += parking::kDt;
    path.samples.push_back({t, state, steering});
  }
}

}  // namespace

ParkingPath simulate_parking_path(const ParkingScenario& scenario, std::span<const ParkingAction> actions,
                                  int control_hz) {
  if (control_hz != parking::kControlHz && control_hz != parking::kSimulationHz)
    throw InputError("simulate_parking_path", "control_hz must be 5 or 15");
  ParkingSim sim(scenario);
  const CollisionChecker collisions(sim.layout());
  ParkingPath path;
  path.samples.push_back({0.0, sim.vehicle(), 0.0});
  const std::size_t per_step = control_hz == parking::kSimulationHz ? parking::kSubstepsPerAction : 1;
  std::size_t next = 0;
  while (next + per_step <= actions.size() && !sim.done()) {
    std::array<ParkingAction, parking::kSubstepsPerAction> held{};
    for (std::size_t k = 0; k < held.size(); ++k) held[k] = actions[next + (per_step == 1 ? 0 : k)];
    next += per_step;
    record_substeps(held, collisions, path);
    const ParkingStepResult result = sim.step_substeps(held);
    path.rewards.push_back(result.reward);
    if (result.success) path.success_step = sim.steps();
    path.collision = path.collision || result.collision;
  }
  path.control_steps = sim.steps();
  return path;
}

ParkingPath simulate_parking_path(const ParkingTrial& trial) {
  return simulate_parking_path(trial.scenario, trial.actions, trial.control_hz);
}

CarPose car_pose_of(const VehicleState& v, double steering) {
  return {
      {static_cast<float>(v.x), static_cast<float>(v.y)}, static_cast<float>(v.heading), static_cast<float>(steering)};
}

CarPose interpolate_car_pose(const VehicleState& a, const VehicleState& b, double steering, double alpha) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  VehicleState v;
  v.x = a.x + (b.x - a.x) * alpha;
  v.y = a.y + (b.y - a.y) * alpha;
  v.heading = a.heading + shortest_angle_delta(a.heading, b.heading) * alpha;
  return car_pose_of(v, steering);
}

CarPose car_pose_at(const ParkingPath& path, double t) {
  if (path.samples.empty()) return {};
  const auto& s = path.samples;
  if (!(t > s.front().t)) return car_pose_of(s.front().vehicle, s.size() > 1 ? s[1].steering : 0.0);
  if (t >= s.back().t) return car_pose_of(s.back().vehicle, s.back().steering);
  const auto later = std::upper_bound(s.begin(), s.end(), t, [](double v, const PathSample& p) { return v < p.t; });
  const auto earlier = later - 1;
  const double alpha = (t - earlier->t) / (later->t - earlier->t);
  return interpolate_car_pose(earlier->vehicle, later->vehicle, later->steering, alpha);
}

std::vector<Vec2f> path_points(const ParkingPath& path) {
  std::vector<Vec2f> points;
  points.reserve(path.samples.size());
  for (const auto& s : path.samples)
    points.push_back({static_cast<float>(s.vehicle.x), static_cast<float>(s.vehicle.y)});
  return points;
}

}  // namespace sc
