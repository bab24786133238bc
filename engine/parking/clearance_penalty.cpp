#include "engine/parking/clearance_penalty.hpp"

#include <algorithm>
#include <cmath>

namespace sc {
namespace {

constexpr double kDiscOffsets[3] = {-5.0 / 3.0, 0.0, 5.0 / 3.0};
// Covers a 5/3 x 2 m slice of the body: sqrt((5/6)^2 + 1^2).
const double kDiscRadius = std::sqrt(25.0 / 36.0 + 1.0);

}  // namespace

// Signed distance from point (px, py) to a box and its gradient (gx, gy) with respect to the point.
double ClearancePenalty::signed_distance(const Box& b, double px, double py, double& gx, double& gy) {
  const double c = b.cos_h, s = b.sin_h;
  const double dx = px - b.x, dy = py - b.y;
  const double lx = c * dx + s * dy, ly = -s * dx + c * dy;  // point in the box frame
  const double ex = std::fabs(lx) - b.half_length, ey = std::fabs(ly) - b.half_width;
  const double sx = lx < 0 ? -1.0 : 1.0, sy = ly < 0 ? -1.0 : 1.0;
  double d, lgx = 0, lgy = 0;
  if (ex > 0 || ey > 0) {
    const double ox = std::max(ex, 0.0), oy = std::max(ey, 0.0);
    d = std::hypot(ox, oy);
    lgx = sx * ox / d;
    lgy = sy * oy / d;
  } else if (ex > ey) {
    d = ex;
    lgx = sx;
  } else {
    d = ey;
    lgy = sy;
  }
  gx = c * lgx - s * lgy;
  gy = s * lgx + c * lgy;
  return d;
}

ClearancePenalty::ClearancePenalty(const ParkingLayout& layout, double margin) : margin_(margin) {
  auto add = [this](const OrientedBox& b) {
    boxes_.push_back({b.x, b.y, std::cos(b.heading), std::sin(b.heading), b.half_length, b.half_width,
                      std::hypot(b.half_length, b.half_width) + kDiscRadius + margin_});
  };
  for (const auto& b : layout.parked_cars) add(b);
  for (const auto& b : layout.walls) add(b);
}

template <typename Visit>
void ClearancePenalty::visit(const VehicleState& state, Visit&& visit_violation) const {
  const double reach = kDiscRadius + margin_;
  const double ch = std::cos(state.heading), sh = std::sin(state.heading);
  for (double offset : kDiscOffsets) {
    const double px = state.x + offset * ch, py = state.y + offset * sh;
    for (const auto& box : boxes_) {
      // Cheap rejection by the box's bounding radius.
      if (std::fabs(px - box.x) > box.reach || std::fabs(py - box.y) > box.reach) continue;
      double gx = 0, gy = 0;
      const double d = signed_distance(box, px, py, gx, gy);
      if (d >= reach) continue;
      ClearanceViolation v;
      v.depth = reach - d;
      v.d_pose[0] = -gx;
      v.d_pose[1] = -gy;
      v.d_pose[2] = -(gx * -offset * sh + gy * offset * ch);
      visit_violation(v);
    }
  }
}

void ClearancePenalty::violations(const VehicleState& state, std::vector<ClearanceViolation>& out) const {
  visit(state, [&out](const ClearanceViolation& v) { out.push_back(v); });
}

double ClearancePenalty::worst_depth(const VehicleState& state) const {
  double worst = 0.0;
  visit(state, [&worst](const ClearanceViolation& v) { worst = std::max(worst, v.depth); });
  return worst;
}

}  // namespace sc
