#pragma once
// Smooth clearance terms for obstacle-aware planning. The 5x2 m car is covered by three discs along its
// axis (radius 1.30 m, a conservative cover of the rectangle); each disc's signed distance to every
// obstacle box gives a hinge residual max(0, radius + margin - distance) with its gradient with respect
// to the car pose (x, y, heading). The exact Box2D test in ParkingSim remains the judge.
#include <vector>

#include "engine/parking/parking_lot.hpp"
#include "engine/parking/vehicle_model.hpp"

namespace sc {

struct ClearanceViolation {
  double depth = 0.0;            // radius + margin - signed distance (> 0)
  double d_pose[3] = {0, 0, 0};  // d depth / d (x, y, heading)
};

class ClearancePenalty {
 public:
  ClearancePenalty(const ParkingLayout& layout, double margin);

  bool empty() const { return boxes_.empty(); }
  // Appends the violated (disc, obstacle) pairs for a car at `state` to `out`.
  void violations(const VehicleState& state, std::vector<ClearanceViolation>& out) const;
  // Largest violation depth at `state` (0 when clear).
  double worst_depth(const VehicleState& state) const;

 private:
  struct Box {
    double x, y, cos_h, sin_h, half_length, half_width;
    double reach;  // bounding radius plus disc radius and margin, for the cheap rejection
  };
  static double signed_distance(const Box& b, double px, double py, double& gx, double& gy);
  template <typename Visit>
  void visit(const VehicleState& state, Visit&& visit_violation) const;

  std::vector<Box> boxes_;
  double margin_;
};

}  // namespace sc
