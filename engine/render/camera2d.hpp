#pragma once
// Maps a rectangle of the world onto a viewport of the framebuffer, keeping the aspect ratio (the world
// rectangle is centred and letterboxed). Pixel coordinates have their origin at the framebuffer's top-left
// corner, like ImGui's, so world-anchored labels line up with the scene.
#include "engine/render/draw_types.hpp"

namespace sc {

struct WorldRect {
  float min_x = 0, min_y = 0, max_x = 1, max_y = 1;
};

struct PixelViewport {
  float x = 0, y = 0, width = 1, height = 1;  // top-left origin
};

enum class WorldYAxis {
  down,  // world +y is down on screen (the parking lot, canvas pixels)
  up,    // world +y is up (mathematical plots)
};

class Camera2D {
 public:
  // Throws InputError when the world rectangle or viewport is empty or not finite.
  Camera2D(WorldRect world, PixelViewport viewport, WorldYAxis y_axis = WorldYAxis::down);

  Vec2f world_to_pixel(Vec2f world) const;
  Vec2f pixel_to_world(Vec2f pixel) const;
  float pixels_per_unit() const { return scale_; }
  const PixelViewport& viewport() const { return viewport_; }
  WorldYAxis y_axis() const { return y_axis_; }
  // The part of the world actually visible in the viewport (at least the requested rectangle).
  WorldRect visible_world() const;

 private:
  PixelViewport viewport_;
  WorldYAxis y_axis_;
  float scale_ = 1;
  Vec2f world_center_;
  Vec2f pixel_center_;
};

}  // namespace sc
