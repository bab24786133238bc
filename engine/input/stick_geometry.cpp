#include "engine/input/stick_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace sc::input {

double length(Vec2 v) { return std::hypot(v.x, v.y); }

double rescale_axial_dead_zone(double v, double dead_zone) {
  const double magnitude = std::abs(v);
  if (magnitude <= dead_zone) return 0.0;
  const double rescaled = std::min(1.0, (magnitude - dead_zone) / (1.0 - dead_zone));
  return std::copysign(rescaled, v);
}

Vec2 rescale_radial_dead_zone(Vec2 v, double dead_zone) {
  const double r = length(v);
  if (r <= dead_zone) return {};
  const double scale = std::min(1.0, (r - dead_zone) / (1.0 - dead_zone)) / r;
  return {v.x * scale, v.y * scale};
}

Vec2 clamp_to_unit_disc(Vec2 v) {
  const double r = length(v);
  if (r <= 1.0) return v;
  return {v.x / r, v.y / r};
}

Vec2 disc_to_square(Vec2 d) {
  const double chebyshev = std::max(std::abs(d.x), std::abs(d.y));
  if (chebyshev == 0.0) return {};
  const double scale = length(d) / chebyshev;
  return {std::clamp(d.x * scale, -1.0, 1.0), std::clamp(d.y * scale, -1.0, 1.0)};
}

Vec2 square_to_disc(Vec2 s) {
  const double chebyshev = std::max(std::abs(s.x), std::abs(s.y));
  if (chebyshev == 0.0) return {};
  const double scale = chebyshev / length(s);
  return {s.x * scale, s.y * scale};
}

}  // namespace sc::input
