#include "engine/render/stroke_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace sc {
namespace {

// The exact triangles of whatever `append` adds to a fresh set of pieces.
template <typename Append>
Triangles tessellate(Append&& append) {
  ConvexPieces pieces;
  append(pieces);
  Triangles t;
  append_triangles(t, pieces);
  return t;
}

double area(const Triangles& t) {  // sum of |triangle areas| (overlaps counted twice)
  double total = 0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) total += std::fabs(cross(t[i + 1] - t[i], t[i + 2] - t[i])) * 0.5;
  return total;
}

TEST(StrokeGeometry, StraightSegmentIsAnExactRectangle) {
  const std::array<Vec2f, 2> pts{Vec2f{0, 0}, Vec2f{10, 0}};
  const Triangles t = tessellate([&](ConvexPieces& p) { append_polyline(p, pts, 2, PathStyle{}, 0.01f); });
  EXPECT_NEAR(area(t), 20.0, 1e-4);
  for (const Vec2f& p : t) EXPECT_NEAR(std::fabs(p.y), 1.0f, 1e-5f);
}

TEST(StrokeGeometry, RightAngleMiterFillsTheCorner) {
  const std::array<Vec2f, 3> pts{Vec2f{0, 0}, Vec2f{10, 0}, Vec2f{10, 10}};
  const Triangles t = tessellate([&](ConvexPieces& p) { append_polyline(p, pts, 2, PathStyle{}, 0.01f); });
  // Two 10x2 quads plus the outer corner square (1x1) as the miter.
  EXPECT_NEAR(area(t), 20 + 20 + 1, 1e-3);
  bool has_miter_tip = false;
  for (const Vec2f& p : t) has_miter_tip |= std::fabs(p.x - 11) < 1e-4f && std::fabs(p.y + 1) < 1e-4f;
  EXPECT_TRUE(has_miter_tip);
}

TEST(StrokeGeometry, SharpTurnBevelsBeyondMiterLimit) {
  const std::array<Vec2f, 3> pts{Vec2f{0, 0}, Vec2f{10, 0}, Vec2f{0, 0.5f}};
  const Triangles t = tessellate([&](ConvexPieces& p) { append_polyline(p, pts, 2, PathStyle{}, 0.01f); });
  for (const Vec2f& p : t) EXPECT_LT(p.x, 12.0f);  // a miter would shoot ~40 units out
}

TEST(StrokeGeometry, RoundCapsAddHalfDiscs) {
  PathStyle style;
  style.cap = LineCap::round;
  const std::array<Vec2f, 2> pts{Vec2f{0, 0}, Vec2f{10, 0}};
  const Triangles t = tessellate([&](ConvexPieces& p) { append_polyline(p, pts, 2, style, 0.001f); });
  EXPECT_NEAR(area(t), 20 + std::numbers::pi, 0.01);
}

TEST(StrokeGeometry, DuplicateAndNonFinitePointsAreIgnored) {
  const std::array<Vec2f, 4> pts{Vec2f{0, 0}, Vec2f{0, 0}, Vec2f{NAN, 1}, Vec2f{5, 0}};
  const Triangles t = tessellate([&](ConvexPieces& p) { append_polyline(p, pts, 1, PathStyle{}, 0.01f); });
  EXPECT_NEAR(area(t), 5.0, 1e-4);
  const std::array<Vec2f, 1> single{Vec2f{1, 1}};
  const Triangles none = tessellate([&](ConvexPieces& p) { append_polyline(p, single, 1, PathStyle{}, 0.01f); });
  EXPECT_TRUE(none.empty());
}

TEST(StrokeGeometry, DashPatternContinuesAcrossVertices) {
  const std::array<Vec2f, 3> pts{Vec2f{0, 0}, Vec2f{3, 0}, Vec2f{3, 7}};
  const auto dashes = dash_polyline(pts, 2, 1);  // on [0,2], [3,5], [6,8], [9,10]
  ASSERT_EQ(dashes.size(), 4u);
  EXPECT_NEAR(dashes[1].front().x, 3, 1e-5);
  EXPECT_NEAR(dashes[1].front().y, 0, 1e-5);
  EXPECT_NEAR(dashes[1].back().y, 2, 1e-5);
  EXPECT_EQ(dashes[3].size(), 2u);
  EXPECT_NEAR(dashes[3].back().y, 7, 1e-5);
}

TEST(StrokeGeometry, CircleAreaConvergesAndSegmentsAreBounded) {
  const Triangles t = tessellate([&](ConvexPieces& p) { append_circle(p, {0, 0}, 10, 0.01f); });
  EXPECT_NEAR(area(t), std::numbers::pi * 100, 1.0);
  EXPECT_EQ(circle_segments(0.001f, 0.25f), 12);
  EXPECT_EQ(circle_segments(1e6f, 0.25f), 256);
  const Triangles ring = tessellate([&](ConvexPieces& p) { append_ring(p, {0, 0}, 10, 2, 0.001f); });
  EXPECT_NEAR(area(ring), std::numbers::pi * (121 - 81), 0.5);
}

TEST(StrokeGeometry, RotatedRectCornersAndArrowTip) {
  const auto corners = rect_corners({{1, 1}, {2, 1}, std::numbers::pi_v<float> / 2});
  EXPECT_NEAR(corners[0].x, 2, 1e-5);  // centre - ex - ey with ex = (0,2), ey = (-1,0)
  EXPECT_NEAR(corners[0].y, -1, 1e-5);
  const Triangles arrow = tessellate([&](ConvexPieces& p) { append_arrow(p, {0, 0}, {10, 0}, 0.5f, 2, 2); });
  float max_x = 0;
  for (const Vec2f& p : arrow) max_x = std::max(max_x, p.x);
  EXPECT_FLOAT_EQ(max_x, 10.0f);
  EXPECT_NEAR(area(arrow), 8 * 0.5 + 2, 1e-4);
}

TEST(StrokeGeometry, SegmentsMeetAtSeamsAndButtEndsAreOutline) {
  // Feathering ramps only outline edges: a ramp where two segments meet would show as a light line.
  const std::array<Vec2f, 3> pts{Vec2f{0, 0}, Vec2f{10, 0}, Vec2f{20, 0}};
  ConvexPieces pieces;
  append_polyline(pieces, pts, 2, PathStyle{}, 0.01f);
  ASSERT_EQ(pieces.piece_count(), 2u);
  int seams = 0, ends = 0;
  for (std::size_t p = 0; p < pieces.piece_count(); ++p) {
    const auto c = pieces.corners(p);
    const auto outline = pieces.outline(p);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Vec2f a = c[i], b = c[(i + 1) % c.size()];
      if (std::fabs(a.x - b.x) > 1e-5f) {
        EXPECT_TRUE(outline[i]) << "the long sides are outline";
      } else if (std::fabs(a.x - 10) < 1e-5f) {
        EXPECT_FALSE(outline[i]) << "where the segments meet";
        ++seams;
      } else {
        EXPECT_TRUE(outline[i]) << "a butt end at x = " << a.x;
        ++ends;
      }
    }
  }
  EXPECT_EQ(seams, 2);
  EXPECT_EQ(ends, 2);
}

TEST(StrokeGeometry, ArrowShaftEndsInASeamUnderTheHead) {
  ConvexPieces pieces;
  append_arrow(pieces, {0, 0}, {10, 0}, 0.5f, 2, 2);
  ASSERT_EQ(pieces.piece_count(), 2u);
  const auto shaft = pieces.corners(0);
  const auto outline = pieces.outline(0);
  for (std::size_t i = 0; i < shaft.size(); ++i) {
    const bool under_head = std::fabs(shaft[i].x - 8) < 1e-5f && std::fabs(shaft[(i + 1) % shaft.size()].x - 8) < 1e-5f;
    EXPECT_EQ(outline[i] != 0, !under_head);
  }
  for (std::uint8_t edge : pieces.outline(1)) EXPECT_TRUE(edge);
}

}  // namespace
}  // namespace sc
