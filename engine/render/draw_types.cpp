#include "engine/render/draw_types.hpp"

#include <algorithm>
#include <cmath>

namespace sc {

std::uint32_t Color::packed_abgr() const {
  auto byte = [](float v) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
  };
  return byte(r) | (byte(g) << 8) | (byte(b) << 16) | (byte(a) << 24);
}

}  // namespace sc
