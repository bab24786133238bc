#pragma once
// Plain value types of the 2D renderer: points in world units, colours, strokes and rotated rectangles.
#include <cstdint>

namespace sc {

struct Vec2f {
  float x = 0;
  float y = 0;
};
inline Vec2f operator+(Vec2f a, Vec2f b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2f operator-(Vec2f a, Vec2f b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2f operator*(Vec2f a, float s) { return {a.x * s, a.y * s}; }
inline float dot(Vec2f a, Vec2f b) { return a.x * b.x + a.y * b.y; }
inline float cross(Vec2f a, Vec2f b) { return a.x * b.y - a.y * b.x; }

// Straight (not premultiplied) RGBA, each channel in [0, 1].
struct Color {
  float r = 0, g = 0, b = 0, a = 1;
  // Color::hex(0x2f80ed) or Color::hex(0x2f80ed, 0.4f).
  static constexpr Color hex(std::uint32_t rgb, float alpha = 1.0f) {
    return {static_cast<float>((rgb >> 16) & 0xff) / 255.0f, static_cast<float>((rgb >> 8) & 0xff) / 255.0f,
            static_cast<float>(rgb & 0xff) / 255.0f, alpha};
  }
  constexpr Color with_alpha(float alpha) const { return {r, g, b, alpha}; }
  std::uint32_t packed_abgr() const;  // 0xAABBGGRR, the byte order of our vertices and of ImU32
};

// Line width either in world units (scales with zoom: a road marking) or in screen pixels (a crisp outline).
struct Stroke {
  enum class Units { world, pixels };
  float width = 1;
  Units units = Units::pixels;
  static constexpr Stroke world(float w) { return {w, Units::world}; }
  static constexpr Stroke pixels(float w) { return {w, Units::pixels}; }
};

enum class LineJoin { miter, round };  // miter falls back to bevel beyond the miter limit
enum class LineCap { butt, round, square };

struct PathStyle {
  LineJoin join = LineJoin::miter;
  LineCap cap = LineCap::butt;
  bool closed = false;
  float miter_limit = 4.0f;  // max miter length / half width before bevelling
};

// A rectangle of size 2*half_size rotated by `angle` radians about its centre. The angle turns the world's
// +x axis toward its +y axis (so on a y-down screen a positive angle turns clockwise).
struct RotatedRect {
  Vec2f center;
  Vec2f half_size;
  float angle = 0;
};

}  // namespace sc
