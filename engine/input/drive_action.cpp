#include "engine/input/drive_action.hpp"

#include <algorithm>
#include <cmath>

namespace sc::input {
namespace {

double sanitized_component(double u) { return std::isfinite(u) ? std::clamp(u, -1.0, 1.0) : 0.0; }
bool valid_component(double u) { return std::isfinite(u) && u >= -1.0 && u <= 1.0; }

}  // namespace

DriveAction sanitized(const DriveAction& action) {
  return {sanitized_component(action.accel), sanitized_component(action.steer)};
}

bool is_valid(const DriveAction& action) { return valid_component(action.accel) && valid_component(action.steer); }

}  // namespace sc::input
