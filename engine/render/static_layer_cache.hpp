#pragma once
// The pixels of a scene layer that does not change from frame to frame (a parking lot: ground, spot lines,
// walls, parked cars), kept in an offscreen single-sample RGBA8 framebuffer and copied into the frame.
//
// Why: on a software rasteriser (llvmpipe) every triangle has a set-up cost, and a lot of 16 parked cars
// is ~5 000 triangles redrawn every frame although it never moves (docs/rendering.md). Copying a region
// of pixels costs a fraction of that. Renderer2D decides when the layer is the same (its key) and when a
// copy gives the same pixels as drawing it; this class only owns the framebuffer.
#include <cstdint>

#include "engine/render/gl_functions.hpp"

namespace sc {

class StaticLayerCache {
 public:
  explicit StaticLayerCache(const GlFunctions& gl) : gl_(gl) {}
  ~StaticLayerCache();
  StaticLayerCache(const StaticLayerCache&) = delete;
  StaticLayerCache& operator=(const StaticLayerCache&) = delete;

  // True when the cache holds the layer `key` drawn at this framebuffer size.
  bool holds(std::uint64_t key, int width, int height) const {
    return valid_ && key == key_ && width == width_ && height == height_;
  }
  // Binds the cache's framebuffer (created or resized to width x height) to draw the layer `key` into;
  // the caller draws it, then binds its own framebuffer again.
  void bind_for_drawing(std::uint64_t key, int width, int height);
  // Copies the box (GL's bottom-left origin) of the cached layer into the same box of `target`, which must be
  // a single-sample framebuffer of the cache's size. Leaves `target` bound.
  void copy_to(GLuint target, int x, int y, int width, int height) const;

 private:
  void release();

  const GlFunctions& gl_;
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  int width_ = 0;
  int height_ = 0;
  std::uint64_t key_ = 0;
  bool valid_ = false;
};

}  // namespace sc
