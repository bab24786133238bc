#include "engine/render/convex_pieces.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sc {
namespace {

void add_rect(ConvexPieces& pieces, float x0, float y0, float x1, float y1, bool left_is_outline = true,
              bool right_is_outline = true) {
  pieces.add_corner({x0, y0}, true);  // bottom
  pieces.add_corner({x1, y0}, right_is_outline);
  pieces.add_corner({x1, y1}, true);  // top
  pieces.add_corner({x0, y1}, left_is_outline);
  pieces.end_piece();
}

// The integral of coverage over the plane: coverage is linear across each triangle, so each triangle
// contributes its area times its corners' mean coverage.
double covered_area(const FeatheredTriangles& t) {
  double total = 0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
    const double area = std::fabs(cross(t[i + 1].position - t[i].position, t[i + 2].position - t[i].position)) * 0.5;
    total += area * (t[i].coverage + t[i + 1].coverage + t[i + 2].coverage) / 3.0;
  }
  return total;
}

TEST(ConvexPieces, FeatheredSquareRampsAcrossItsEdgeAndKeepsItsArea) {
  ConvexPieces pieces;
  add_rect(pieces, 0, 0, 10, 10);
  FeatheredTriangles t;
  append_feathered(t, pieces, 1.0f);
  for (const FeatheredVertex& v : t) {
    const float edge = v.coverage > 0.5f ? 0.5f : -0.5f;  // inset half a feather, or pushed out by it
    EXPECT_NEAR(std::fabs(v.position.x - 5), 5 - edge, 1e-4) << v.position.x << "," << v.position.y;
    EXPECT_NEAR(std::fabs(v.position.y - 5), 5 - edge, 1e-4) << v.position.x << "," << v.position.y;
  }
  // Centred ramps keep the area; mitred corners add (4/3) h^2 each side pair, h = half a feather.
  EXPECT_NEAR(covered_area(t), 100 + 4.0 / 3.0 * 0.25, 1e-3);
}

TEST(ConvexPieces, SeamsGetNoRamp) {
  ConvexPieces pieces;
  add_rect(pieces, 0, 0, 10, 10, true, false);
  add_rect(pieces, 10, 0, 20, 10, false, true);
  FeatheredTriangles t;
  append_feathered(t, pieces, 1.0f);
  bool core_reaches_seam = false;
  for (const FeatheredVertex& v : t) {
    const bool near_seam = std::fabs(v.position.x - 10) < 0.9f && v.position.y > 1 && v.position.y < 9;
    if (near_seam) {
      EXPECT_EQ(v.coverage, 1.0f) << "no ramp across x = 10 at y = " << v.position.y;
    }
    // Each core reaches a sliver across the seam, so no pixel centre falls between the two.
    const float past_seam = std::fabs(v.position.x - 10);
    core_reaches_seam |= v.coverage == 1.0f && past_seam > 0.001f && past_seam < 0.05f;
  }
  EXPECT_TRUE(core_reaches_seam);
  const double exact = 200 + 4.0 / 3.0 * 0.25, slivers = 2 * 10 * 0.05;
  EXPECT_GT(covered_area(t), exact);
  EXPECT_LT(covered_area(t), exact + slivers);
}

TEST(ConvexPieces, CoresComeBeforeAllRamps) {
  ConvexPieces pieces;
  add_rect(pieces, 0, 0, 4, 4);
  add_rect(pieces, 2, 2, 6, 6);
  FeatheredTriangles t;
  append_feathered(t, pieces, 1.0f);
  bool in_ramps = false;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
    const bool ramp = t[i].coverage < 1 || t[i + 1].coverage < 1 || t[i + 2].coverage < 1;
    EXPECT_TRUE(ramp || !in_ramps) << "a core triangle after the ramps began, at vertex " << i;
    in_ramps |= ramp;
  }
  EXPECT_TRUE(in_ramps);
}

TEST(ConvexPieces, PieceThinnerThanTheFeatherShrinksToALine) {
  ConvexPieces pieces;
  add_rect(pieces, 0, 0, 10, 0.2f);
  FeatheredTriangles t;
  append_feathered(t, pieces, 1.0f);
  for (const FeatheredVertex& v : t) {
    if (v.coverage == 1.0f) {
      EXPECT_NEAR(v.position.y, 0.1f, 1e-5f) << "the core collapses onto the middle line";
    }
    EXPECT_GE(v.position.y, -0.1f - 1e-5f);  // the ramp is as wide as the piece, not a whole feather
    EXPECT_LE(v.position.y, 0.3f + 1e-5f);
  }
}

TEST(ConvexPieces, RepeatedCornersMergeAndDegeneratePiecesDrop) {
  ConvexPieces pieces;
  pieces.add_corner({0, 0}, true);
  pieces.add_corner({0, 0}, false);  // the later corner's edge (a seam to {1, 0}) is kept
  pieces.add_corner({1, 0}, true);
  pieces.add_corner({1, 1}, true);
  pieces.add_corner({0, 0}, true);  // closes onto the first corner
  pieces.end_piece();
  pieces.add_corner({5, 5}, true);
  pieces.add_corner({6, 5}, true);
  pieces.add_corner({6, 5}, true);
  pieces.end_piece();  // two distinct corners: no piece
  ASSERT_EQ(pieces.piece_count(), 1u);
  ASSERT_EQ(pieces.corners(0).size(), 3u);
  EXPECT_FALSE(pieces.outline(0)[0]);
  EXPECT_TRUE(pieces.outline(0)[1]);
  EXPECT_TRUE(pieces.outline(0)[2]);
}

}  // namespace
}  // namespace sc
