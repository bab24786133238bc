#include "engine/render/camera2d.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace sc {

Camera2D::Camera2D(WorldRect world, PixelViewport viewport, WorldYAxis y_axis) : viewport_(viewport), y_axis_(y_axis) {
  const float world_w = world.max_x - world.min_x, world_h = world.max_y - world.min_y;
  if (!(world_w > 0) || !(world_h > 0) || !std::isfinite(world_w) || !std::isfinite(world_h))
    throw InputError("Camera2D", "world rectangle must have a positive finite size");
  if (!(viewport.width > 0) || !(viewport.height > 0))
    throw InputError("Camera2D", "viewport must have a positive size");
  scale_ = std::min(viewport.width / world_w, viewport.height / world_h);
  world_center_ = {(world.min_x + world.max_x) * 0.5f, (world.min_y + world.max_y) * 0.5f};
  pixel_center_ = {viewport.x + viewport.width * 0.5f, viewport.y + viewport.height * 0.5f};
}

Vec2f Camera2D::world_to_pixel(Vec2f world) const {
  const float sy = y_axis_ == WorldYAxis::down ? scale_ : -scale_;
  return {pixel_center_.x + (world.x - world_center_.x) * scale_, pixel_center_.y + (world.y - world_center_.y) * sy};
}

Vec2f Camera2D::pixel_to_world(Vec2f pixel) const {
  const float sy = y_axis_ == WorldYAxis::down ? scale_ : -scale_;
  return {world_center_.x + (pixel.x - pixel_center_.x) / scale_, world_center_.y + (pixel.y - pixel_center_.y) / sy};
}

WorldRect Camera2D::visible_world() const {
  const float half_w = viewport_.width * 0.5f / scale_, half_h = viewport_.height * 0.5f / scale_;
  return {world_center_.x - half_w, world_center_.y - half_h, world_center_.x + half_w, world_center_.y + half_h};
}

}  // namespace sc
