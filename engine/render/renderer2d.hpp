#pragma once
// OpenGL 3.3 core renderer of 2D scenes in world units. Primitives are tessellated on the CPU with the current
// camera and appended to one vertex batch, drawn in order (painter's algorithm) with as few draw calls as the
// state allows: one per run of opaque/translucent primitives sharing a clip rectangle, plus one per ghost
// ribbon (each ghost uses its own stencil value so overlapping parts of one ribbon are blended only once).
// Edges are anti-aliased in the geometry (a one-pixel feathered ramp, engine/render/convex_pieces.hpp), so a
// single-sample framebuffer looks smooth and a multisampled one needs no more than it has.
//
//   Renderer2D renderer(context);             // loads shaders/scene.{vert,frag}
//   renderer.begin_frame(Color::hex(0x20242c));
//   renderer.set_camera(Camera2D({0, 0, 20, 12}, {0, 0, w, h}, WorldYAxis::down));
//   renderer.fill_rect({{5, 5}, {2.4f, 1.0f}, 0.3f}, Color::hex(0x3d7be0));
//   renderer.end_frame();                     // flushes; ImGui may draw on top afterwards
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/render/camera2d.hpp"
#include "engine/render/draw_types.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/shader_program.hpp"
#include "engine/render/static_layer_cache.hpp"
#include "engine/render/stroke_geometry.hpp"

namespace sc {

struct DashPattern {
  float dash = 1;  // lengths in the stroke's units
  float gap = 1;
};

struct ArrowHead {
  float length = 12;  // in the stroke's units
  float width = 10;
};

struct RenderStats {
  int draw_calls = 0;
  int vertices = 0;             // drawn this frame (a static layer copied from the cache is not drawn)
  int static_layer_copies = 0;  // static layers copied from the cache instead of drawn
};

class Renderer2D {
 public:
  explicit Renderer2D(GlContext& context);
  ~Renderer2D();
  Renderer2D(const Renderer2D&) = delete;
  Renderer2D& operator=(const Renderer2D&) = delete;

  // Resets every piece of GL state we depend on (so a frame never depends on what came before), binds the
  // context's framebuffer, clears its colour (the stencil is cleared under the ghost ribbons when they are
  // drawn; depth is never used), and sets a camera showing the whole framebuffer in pixels.
  void begin_frame(Color clear);
  // Draws everything batched since begin_frame. GL state is left for ImGui to draw on top.
  void end_frame();

  // Primitives after this use `camera`, clipped to its viewport.
  void set_camera(const Camera2D& camera);
  const Camera2D& camera() const { return camera_; }

  void fill_rect(const RotatedRect& rect, Color color);
  void outline_rect(const RotatedRect& rect, Stroke stroke, Color color);
  void fill_polygon(std::span<const Vec2f> convex_corners, Color color);
  void polyline(std::span<const Vec2f> points, Stroke stroke, Color color, const PathStyle& style = {});
  void dashed_polyline(std::span<const Vec2f> points, Stroke stroke, DashPattern pattern, Color color,
                       const PathStyle& style = {});
  void fill_circle(Vec2f center, float radius, Color color);
  void outline_circle(Vec2f center, float radius, Stroke stroke, Color color);
  // A translucent path (e.g. an expert's ghost trajectory): where the ribbon overlaps itself it is still
  // blended only once, so its colour stays even. Use a colour with alpha < 1.
  void ghost_ribbon(std::span<const Vec2f> points, Stroke stroke, Color color, const PathStyle& style = {});
  void arrow(Vec2f from, Vec2f to, Stroke stroke, ArrowHead head, Color color);

  // A static layer: what is drawn between these two calls (e.g. a parking lot) is drawn once into a cache
  // and copied from there in later frames while it stays the same. "The same" is decided on the layer's own
  // tessellated geometry (vertices, colours, clips) and the framebuffer size, so the copy cannot go stale.
  // It is only used where it gives exactly the pixels drawing would: a single-sample target, and a layer
  // that starts by covering its viewport with an opaque ground (fill_rect's scissored clear), draws nothing
  // outside that viewport and no ghost ribbons. Otherwise the layer is drawn as usual. Layers do not nest.
  void begin_static_layer();
  void end_static_layer();

  // Counts of the last end_frame().
  RenderStats last_frame_stats() const { return stats_; }

 private:
  struct Vertex {
    float x, y;
    std::uint32_t abgr;
  };
  struct Batch {
    std::size_t first = 0;
    std::size_t count = 0;
    PixelViewport clip;
    int stencil_ref = 0;         // 0: ordinary; >0: ghost drawn once per pixel with this stencil value
    std::optional<Color> clear;  // set: no triangles, the clip rectangle is cleared to this colour
  };

  // A stroke narrower than a pixel is drawn one pixel wide with its colour's alpha scaled by its width: the
  // feathered edge needs a pixel to ramp across, and the line keeps the same weight.
  struct ThinStroke {
    float width;  // world units
    Color color;
  };

  struct ScissorBox {  // GL's bottom-left origin
    int x, y, width, height;
  };

  // An opaque upright rectangle over the whole of a pixel-aligned viewport (a scene's ground) is a scissored
  // clear: the same pixels, without blending and shading every one of them.
  bool fills_viewport(const RotatedRect& rect, Color color) const;
  float to_world(Stroke stroke) const;
  ThinStroke thin_stroke(Stroke stroke, Color color) const;
  float chord_error_world() const;  // a quarter pixel in world units
  // Feathers the pieces (a one-pixel anti-aliasing ramp on their outline) and batches them.
  void push(const ConvexPieces& pieces, Color color, int stencil_ref = 0);
  void flush();
  // The pixels the batched ghost ribbons can touch, if there are any.
  std::optional<ScissorBox> ghost_bounds() const;
  void clear_stencil(const ScissorBox& box);
  ScissorBox scissor_of(const PixelViewport& clip) const;
  // Whether the batches from `first` on form a layer a copy can stand in for (see begin_static_layer).
  bool copyable_layer(std::size_t first) const;
  std::uint64_t layer_key(std::size_t first) const;

  GlContext& context_;
  const GlFunctions& gl_;
  ShaderProgram program_;
  GLint framebuffer_size_uniform_ = -1;
  GLuint vertex_array_ = 0;
  GLuint vertex_buffer_ = 0;
  std::size_t buffer_capacity_ = 0;
  Camera2D camera_;
  std::vector<Vertex> vertices_;
  std::vector<Batch> batches_;
  ConvexPieces scratch_;
  FeatheredTriangles feathered_;
  int next_ghost_ref_ = 1;
  bool in_frame_ = false;
  bool single_sample_target_ = false;
  std::optional<std::size_t> layer_first_batch_;  // set between begin_ and end_static_layer
  StaticLayerCache layer_cache_;
  RenderStats stats_;
};

}  // namespace sc
