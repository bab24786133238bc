#include "engine/render/renderer2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "engine/core/error.hpp"

namespace sc {
namespace {

constexpr int kMaxGhostsPerStencilClear = 255;  // 8-bit stencil

Camera2D pixel_camera(int width, int height) {
  const float w = static_cast<float>(std::max(1, width)), h = static_cast<float>(std::max(1, height));
  return Camera2D({0, 0, w, h}, {0, 0, w, h}, WorldYAxis::down);
}

bool same_clip(const PixelViewport& a, const PixelViewport& b) {
  return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

bool whole_pixel(float v) { return std::abs(v - std::round(v)) < 1e-3f; }

}  // namespace

Renderer2D::Renderer2D(GlContext& context)
    : context_(context),
      gl_(context.gl()),
      program_(context.gl(), "scene.vert", "scene.frag"),
      camera_(pixel_camera(context.width(), context.height())),
      layer_cache_(context.gl()) {
  framebuffer_size_uniform_ = program_.uniform("u_framebuffer_size");
  gl_.GenVertexArrays(1, &vertex_array_);
  gl_.GenBuffers(1, &vertex_buffer_);
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  gl_.EnableVertexAttribArray(0);
  gl_.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
  gl_.EnableVertexAttribArray(1);
  gl_.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, abgr)));
  gl_.BindVertexArray(0);
  GLint sample_buffers = 0;
  gl_.BindFramebuffer(GL_FRAMEBUFFER, context.target_framebuffer());
  gl_.GetIntegerv(GL_SAMPLE_BUFFERS, &sample_buffers);
  single_sample_target_ = sample_buffers == 0;
  throw_on_gl_error(gl_, "creating the scene renderer");
}

Renderer2D::~Renderer2D() {
  gl_.DeleteBuffers(1, &vertex_buffer_);
  gl_.DeleteVertexArrays(1, &vertex_array_);
}

void Renderer2D::begin_frame(Color clear) {
  const int w = context_.width(), h = context_.height();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, context_.target_framebuffer());
  gl_.Viewport(0, 0, w, h);
  gl_.Disable(GL_SCISSOR_TEST);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_CULL_FACE);
  gl_.Disable(GL_STENCIL_TEST);
  gl_.Disable(GL_PRIMITIVE_RESTART);
  gl_.Disable(GL_FRAMEBUFFER_SRGB);
  gl_.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  gl_.Enable(GL_MULTISAMPLE);
  gl_.Enable(GL_BLEND);
  gl_.BlendEquation(GL_FUNC_ADD);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_.DepthMask(GL_TRUE);
  gl_.StencilMask(0xFF);
  gl_.StencilFunc(GL_ALWAYS, 0, 0xFF);
  gl_.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_2D, 0);
  gl_.UseProgram(0);
  gl_.BindVertexArray(0);
  gl_.ClearColor(clear.r, clear.g, clear.b, clear.a);
  gl_.ClearStencil(0);
  // Nothing tests depth, and only ghost ribbons use the stencil: flush() clears it under them alone. On a
  // software rasteriser a full-screen depth/stencil clear costs as much as a layer of pixels.
  gl_.Clear(GL_COLOR_BUFFER_BIT);
  vertices_.clear();
  batches_.clear();
  next_ghost_ref_ = 1;
  camera_ = pixel_camera(w, h);
  stats_ = {};
  layer_first_batch_.reset();
  in_frame_ = true;
}

void Renderer2D::end_frame() {
  if (!in_frame_) throw InputError("Renderer2D", "end_frame() without begin_frame()");
  flush();
  gl_.Disable(GL_STENCIL_TEST);
  gl_.Disable(GL_SCISSOR_TEST);
  gl_.BindVertexArray(0);
  gl_.UseProgram(0);
  in_frame_ = false;
}

void Renderer2D::begin_static_layer() {
  if (!in_frame_) throw InputError("Renderer2D", "begin_static_layer() outside begin_frame()/end_frame()");
  if (layer_first_batch_) throw InputError("Renderer2D", "static layers do not nest");
  flush();  // what came before is drawn below the layer
  layer_first_batch_ = batches_.size();
}

void Renderer2D::end_static_layer() {
  if (!layer_first_batch_) throw InputError("Renderer2D", "end_static_layer() without begin_static_layer()");
  const std::size_t first = *layer_first_batch_;
  layer_first_batch_.reset();
  if (!single_sample_target_ || !copyable_layer(first)) return;  // drawn with the rest, as usual
  const int w = context_.width(), h = context_.height();
  const std::uint64_t key = layer_key(first);
  const ScissorBox box = scissor_of(batches_[first].clip);
  if (layer_cache_.holds(key, w, h)) {
    vertices_.clear();
    batches_.clear();
  } else {
    layer_cache_.bind_for_drawing(key, w, h);
    flush();
  }
  gl_.Disable(GL_SCISSOR_TEST);
  layer_cache_.copy_to(context_.target_framebuffer(), box.x, box.y, box.width, box.height);
  ++stats_.static_layer_copies;
}

bool Renderer2D::copyable_layer(std::size_t first) const {
  if (first >= batches_.size() || !batches_[first].clear) return false;
  const PixelViewport& ground = batches_[first].clip;
  const int fb_w = context_.width(), fb_h = context_.height();
  if (ground.x < 0 || ground.y < 0 || ground.x + ground.width > static_cast<float>(fb_w) ||
      ground.y + ground.height > static_cast<float>(fb_h))
    return false;
  for (std::size_t i = first; i < batches_.size(); ++i) {
    const PixelViewport& c = batches_[i].clip;
    if (batches_[i].stencil_ref != 0) return false;
    if (c.x < ground.x || c.y < ground.y || c.x + c.width > ground.x + ground.width ||
        c.y + c.height > ground.y + ground.height)
      return false;
  }
  return true;
}

// FNV-style mixing over the layer's words: its vertices (positions and colours), its batches and the
// framebuffer size. 16 000 vertices hash in well under a tenth of a millisecond.
std::uint64_t Renderer2D::layer_key(std::size_t first) const {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  auto mix = [&h](std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0x100000001b3ULL;
  };
  auto bits = [](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return static_cast<std::uint64_t>(u);
  };
  mix(static_cast<std::uint64_t>(context_.width()) << 32 | static_cast<std::uint32_t>(context_.height()));
  const std::size_t vertex_begin = batches_[first].first;
  for (std::size_t i = vertex_begin; i < vertices_.size(); ++i)
    mix(bits(vertices_[i].x) << 32 | bits(vertices_[i].y)), mix(vertices_[i].abgr);
  for (std::size_t i = first; i < batches_.size(); ++i) {
    const Batch& b = batches_[i];
    mix(b.first), mix(b.count), mix(bits(b.clip.x) << 32 | bits(b.clip.y));
    mix(bits(b.clip.width) << 32 | bits(b.clip.height));
    mix(b.clear ? b.clear->packed_abgr() | 1ULL << 40 : 0);
  }
  return h;
}

void Renderer2D::set_camera(const Camera2D& camera) { camera_ = camera; }

float Renderer2D::to_world(Stroke stroke) const {
  return stroke.units == Stroke::Units::world ? stroke.width : stroke.width / camera_.pixels_per_unit();
}

float Renderer2D::chord_error_world() const { return 0.25f / camera_.pixels_per_unit(); }

Renderer2D::ThinStroke Renderer2D::thin_stroke(Stroke stroke, Color color) const {
  const float width = to_world(stroke), pixel = 1.0f / camera_.pixels_per_unit();
  if (!(width < pixel)) return {width, color};
  return {pixel, color.with_alpha(color.a * std::max(0.0f, width / pixel))};
}

void Renderer2D::push(const ConvexPieces& pieces, Color color, int stencil_ref) {
  if (!in_frame_) throw InputError("Renderer2D", "drawing outside begin_frame()/end_frame()");
  if (pieces.empty()) return;
  feathered_.clear();
  append_feathered(feathered_, pieces, 1.0f / camera_.pixels_per_unit());
  const std::uint32_t inside = color.packed_abgr(), outside = color.with_alpha(0).packed_abgr();
  const std::size_t first = vertices_.size();
  for (const FeatheredVertex& v : feathered_) {
    const Vec2f px = camera_.world_to_pixel(v.position);
    vertices_.push_back({px.x, px.y, v.coverage > 0.5f ? inside : outside});
  }
  const PixelViewport& clip = camera_.viewport();
  if (stencil_ref == 0 && !batches_.empty() && batches_.back().stencil_ref == 0 && !batches_.back().clear &&
      same_clip(batches_.back().clip, clip)) {
    batches_.back().count += feathered_.size();
  } else {
    batches_.push_back({first, feathered_.size(), clip, stencil_ref, std::nullopt});
  }
}

bool Renderer2D::fills_viewport(const RotatedRect& rect, Color color) const {
  const PixelViewport& v = camera_.viewport();
  if (rect.angle != 0.0f || color.a < 1.0f) return false;
  if (!whole_pixel(v.x) || !whole_pixel(v.y) || !whole_pixel(v.x + v.width) || !whole_pixel(v.y + v.height))
    return false;
  const Vec2f a = camera_.world_to_pixel(rect.center - rect.half_size);
  const Vec2f b = camera_.world_to_pixel(rect.center + rect.half_size);
  constexpr float slack = 1e-3f;
  return std::min(a.x, b.x) <= v.x + slack && std::max(a.x, b.x) >= v.x + v.width - slack &&
         std::min(a.y, b.y) <= v.y + slack && std::max(a.y, b.y) >= v.y + v.height - slack;
}

void Renderer2D::fill_rect(const RotatedRect& rect, Color color) {
  if (!in_frame_) throw InputError("Renderer2D", "drawing outside begin_frame()/end_frame()");
  if (fills_viewport(rect, color)) {
    batches_.push_back({vertices_.size(), 0, camera_.viewport(), 0, color});
    return;
  }
  scratch_.clear();
  append_convex_polygon(scratch_, rect_corners(rect));
  push(scratch_, color);
}

void Renderer2D::outline_rect(const RotatedRect& rect, Stroke stroke, Color color) {
  scratch_.clear();
  PathStyle style;
  style.closed = true;
  const ThinStroke thin = thin_stroke(stroke, color);
  append_polyline(scratch_, rect_corners(rect), thin.width, style, chord_error_world());
  push(scratch_, thin.color);
}

void Renderer2D::fill_polygon(std::span<const Vec2f> convex_corners, Color color) {
  scratch_.clear();
  append_convex_polygon(scratch_, convex_corners);
  push(scratch_, color);
}

void Renderer2D::polyline(std::span<const Vec2f> points, Stroke stroke, Color color, const PathStyle& style) {
  scratch_.clear();
  const ThinStroke thin = thin_stroke(stroke, color);
  append_polyline(scratch_, points, thin.width, style, chord_error_world());
  push(scratch_, thin.color);
}

void Renderer2D::dashed_polyline(std::span<const Vec2f> points, Stroke stroke, DashPattern pattern, Color color,
                                 const PathStyle& style) {
  const float scale = stroke.units == Stroke::Units::world ? 1.0f : 1.0f / camera_.pixels_per_unit();
  PathStyle dash_style = style;
  dash_style.closed = false;
  scratch_.clear();
  const ThinStroke thin = thin_stroke(stroke, color);
  for (const auto& dash : dash_polyline(points, pattern.dash * scale, pattern.gap * scale))
    append_polyline(scratch_, dash, thin.width, dash_style, chord_error_world());
  push(scratch_, thin.color);
}

void Renderer2D::fill_circle(Vec2f center, float radius, Color color) {
  scratch_.clear();
  append_circle(scratch_, center, radius, chord_error_world());
  push(scratch_, color);
}

void Renderer2D::outline_circle(Vec2f center, float radius, Stroke stroke, Color color) {
  scratch_.clear();
  const ThinStroke thin = thin_stroke(stroke, color);
  append_ring(scratch_, center, radius, thin.width, chord_error_world());
  push(scratch_, thin.color);
}

void Renderer2D::ghost_ribbon(std::span<const Vec2f> points, Stroke stroke, Color color, const PathStyle& style) {
  scratch_.clear();
  const ThinStroke thin = thin_stroke(stroke, color);
  append_polyline(scratch_, points, thin.width, style, chord_error_world());
  if (scratch_.empty()) return;
  push(scratch_, thin.color, next_ghost_ref_);
  next_ghost_ref_ = next_ghost_ref_ % kMaxGhostsPerStencilClear + 1;
}

void Renderer2D::arrow(Vec2f from, Vec2f to, Stroke stroke, ArrowHead head, Color color) {
  const float scale = stroke.units == Stroke::Units::world ? 1.0f : 1.0f / camera_.pixels_per_unit();
  scratch_.clear();
  append_arrow(scratch_, from, to, to_world(stroke), head.length * scale, head.width * scale);
  push(scratch_, color);
}

void Renderer2D::flush() {
  stats_.vertices += static_cast<int>(vertices_.size());
  if (batches_.empty()) return;
  const int fb_w = context_.width(), fb_h = context_.height();
  gl_.UseProgram(program_.id());
  gl_.Uniform2f(framebuffer_size_uniform_, static_cast<float>(fb_w), static_cast<float>(fb_h));
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  const std::size_t bytes = vertices_.size() * sizeof(Vertex);
  if (bytes > buffer_capacity_) {
    buffer_capacity_ = std::max(bytes, buffer_capacity_ * 2);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(buffer_capacity_), nullptr, GL_STREAM_DRAW);
  }
  gl_.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), vertices_.data());
  gl_.Enable(GL_SCISSOR_TEST);
  const std::optional<ScissorBox> ghosts = ghost_bounds();
  if (ghosts) clear_stencil(*ghosts);
  int previous_ref = 0;
  for (const Batch& batch : batches_) {
    const ScissorBox box = scissor_of(batch.clip);
    gl_.Scissor(box.x, box.y, box.width, box.height);
    if (batch.clear) {
      gl_.ClearColor(batch.clear->r, batch.clear->g, batch.clear->b, batch.clear->a);
      gl_.Clear(GL_COLOR_BUFFER_BIT);
      continue;
    }
    if (batch.stencil_ref > 0) {
      if (batch.stencil_ref < previous_ref) {  // wrapped after 255 ghosts: start the stencil afresh
        clear_stencil(*ghosts);
        gl_.Scissor(box.x, box.y, box.width, box.height);
      }
      gl_.Enable(GL_STENCIL_TEST);
      gl_.StencilFunc(GL_NOTEQUAL, batch.stencil_ref, 0xFF);
      gl_.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      previous_ref = batch.stencil_ref;
    } else {
      gl_.Disable(GL_STENCIL_TEST);
    }
    gl_.DrawArrays(GL_TRIANGLES, static_cast<GLint>(batch.first), static_cast<GLsizei>(batch.count));
    ++stats_.draw_calls;
  }
  vertices_.clear();
  batches_.clear();
}

std::optional<Renderer2D::ScissorBox> Renderer2D::ghost_bounds() const {
  float min_x = 1e30f, min_y = 1e30f, max_x = -1e30f, max_y = -1e30f;
  for (const Batch& batch : batches_) {
    if (batch.stencil_ref == 0) continue;
    for (std::size_t i = batch.first; i < batch.first + batch.count; ++i) {
      min_x = std::min(min_x, vertices_[i].x);
      max_x = std::max(max_x, vertices_[i].x);
      min_y = std::min(min_y, vertices_[i].y);
      max_y = std::max(max_y, vertices_[i].y);
    }
  }
  if (min_x > max_x) return std::nullopt;
  const int fb_w = context_.width(), fb_h = context_.height();
  const int x0 = std::clamp(static_cast<int>(std::floor(min_x)), 0, fb_w);
  const int x1 = std::clamp(static_cast<int>(std::ceil(max_x)), 0, fb_w);
  const int y0 = std::clamp(static_cast<int>(std::floor(min_y)), 0, fb_h);
  const int y1 = std::clamp(static_cast<int>(std::ceil(max_y)), 0, fb_h);
  return ScissorBox{x0, fb_h - y1, x1 - x0, y1 - y0};
}

// Scissor takes a bottom-left origin; our pixels have a top-left origin.
Renderer2D::ScissorBox Renderer2D::scissor_of(const PixelViewport& clip) const {
  const int x0 = static_cast<int>(std::floor(clip.x));
  const int y1 = static_cast<int>(std::ceil(clip.y + clip.height));
  const int x1 = static_cast<int>(std::ceil(clip.x + clip.width));
  const int y0 = static_cast<int>(std::floor(clip.y));
  return {x0, context_.height() - y1, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

void Renderer2D::clear_stencil(const ScissorBox& box) {
  gl_.Scissor(box.x, box.y, box.width, box.height);
  gl_.Clear(GL_STENCIL_BUFFER_BIT);
}

}  // namespace sc
