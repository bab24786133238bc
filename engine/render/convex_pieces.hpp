#pragma once
// A shape as convex pieces whose edges are either outline (the shape's boundary) or seams (shared with another
// piece of the same shape, e.g. where a stroke's segment meets its join). Tessellation builds pieces; they then
// become exact triangles, or feathered triangles for analytic anti-aliasing.
//
// Why feathering: a CPU rasteriser (llvmpipe) pays for 4x MSAA on every sample of every pixel, clear and
// resolve included; a one-pixel coverage ramp across the outline gives a single-sample framebuffer edges as
// smooth as MSAA. Spec: coverage is 1 on the outline inset by half a feather width and falls linearly to 0 on
// the outline pushed out by half a feather width (so the ramp is centred on the true edge and the shape keeps
// its weight); corners between two outline edges are mitred; a seam keeps its place and gets no ramp, so
// pieces join without a visible line. A piece thinner than one feather width gets a narrower ramp (its core
// shrinks to a line, never turns inside out).
//
//   ConvexPieces pieces;
//   pieces.add_corner({0, 0}, true);   // the edge from this corner to the next is outline
//   pieces.add_corner({4, 0}, true);
//   pieces.add_corner({4, 2}, false);  // a seam back to the first corner
//   pieces.end_piece();
#include <cstdint>
#include <span>
#include <vector>

#include "engine/render/draw_types.hpp"

namespace sc {

using Triangles = std::vector<Vec2f>;  // every 3 points form one triangle

struct FeatheredVertex {
  Vec2f position;
  float coverage = 1;  // 1 inside, 0 on the outer edge of the ramp; interpolated across each triangle
};
using FeatheredTriangles = std::vector<FeatheredVertex>;

class ConvexPieces {
 public:
  // Adds a corner to the open piece; `outline` says whether the edge to the next corner (wrapping to the
  // first) is part of the shape's outline.
  void add_corner(Vec2f corner, bool outline);
  // Closes the open piece; repeated corners are merged and a piece of fewer than 3 distinct corners dropped.
  void end_piece();
  void clear();
  bool empty() const { return piece_ends_.empty(); }
  std::size_t piece_count() const { return piece_ends_.size(); }
  std::span<const Vec2f> corners(std::size_t piece) const;
  std::span<const std::uint8_t> outline(std::size_t piece) const;  // outline(p)[i]: edge from corner i

 private:
  std::size_t piece_begin(std::size_t piece) const { return piece == 0 ? 0 : piece_ends_[piece - 1]; }

  std::vector<Vec2f> corners_;
  std::vector<std::uint8_t> outline_;
  std::vector<std::size_t> piece_ends_;
};

// The pieces' exact area as a fan of triangles per piece.
void append_triangles(Triangles& out, const ConvexPieces& pieces);

// Feathered triangles with a ramp `feather` wide (one pixel, in the pieces' units). The cores of all pieces
// come first and the ramps after them, so a draw that writes each pixel once (the renderer's ghost ribbons)
// lets a core win over a neighbour's ramp.
void append_feathered(FeatheredTriangles& out, const ConvexPieces& pieces, float feather);

}  // namespace sc
