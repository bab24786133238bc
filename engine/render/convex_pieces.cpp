#include "engine/render/convex_pieces.hpp"

#include <algorithm>
#include <cmath>

namespace sc {
namespace {

constexpr float kSameCorner = 1e-6f;
constexpr float kMaxOffsetInHalfFeathers = 4.0f;  // caps the mitre of very sharp corners
// Pieces reach this far (in feathers) across their seams. Neighbours computed separately (a round join's arc,
// a segment's end) meet along slightly different lines; on a single-sample target a pixel whose centre falls
// in the hairline between them would stay unpainted, a dot in a ribbon.
constexpr float kSeamOverlap = 1.0f / 64.0f;

float length(Vec2f v) { return std::sqrt(dot(v, v)); }

struct PieceOffsets {
  std::vector<Vec2f> inner;  // where coverage reaches 1
  std::vector<Vec2f> outer;  // where coverage reaches 0
};

// Outward unit normal of each edge (corner i to i+1) of a convex piece, whichever way it winds.
void outward_normals(std::span<const Vec2f> c, std::vector<Vec2f>& normals) {
  const std::size_t n = c.size();
  float twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) twice_area += cross(c[i], c[(i + 1) % n]);
  const float side = twice_area >= 0 ? 1.0f : -1.0f;  // counter-clockwise: the outside is on the right
  normals.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2f d = c[(i + 1) % n] - c[i];
    const float len = length(d);
    normals[i] = len > 0 ? Vec2f{d.y * side / len, -d.x * side / len} : Vec2f{};
  }
}

// Half the ramp width a piece can take: half a feather, or less where the piece is thinner across an outline
// edge than one feather (then its core shrinks to a line).
float half_ramp(std::span<const Vec2f> c, std::span<const std::uint8_t> outline, const std::vector<Vec2f>& normals,
                float feather) {
  float half = feather * 0.5f;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!outline[i]) continue;
    float depth = 0;  // how far the piece reaches inward from this edge
    for (const Vec2f& p : c) depth = std::max(depth, dot(normals[i], c[i] - p));
    half = std::min(half, depth * 0.5f);
  }
  return half;
}

// The point at signed distances d_prev and d_next outside the lines of the edges before and after a corner.
Vec2f offset_corner(Vec2f n_prev, Vec2f n_next, float d_prev, float d_next, float max_offset) {
  const float det = cross(n_prev, n_next);
  Vec2f x;
  if (std::fabs(det) < 1e-4f) {  // straight on: both edges share a line
    x = n_next * std::max(d_prev, d_next);
  } else {
    x = {(d_prev * n_next.y - d_next * n_prev.y) / det, (n_prev.x * d_next - n_next.x * d_prev) / det};
  }
  const float len = length(x);
  return len > max_offset ? x * (max_offset / len) : x;
}

void offsets_of(std::span<const Vec2f> c, std::span<const std::uint8_t> outline, float feather,
                std::vector<Vec2f>& normals, PieceOffsets& out) {
  outward_normals(c, normals);
  const float half = half_ramp(c, outline, normals, feather);
  const float max_offset = kMaxOffsetInHalfFeathers * feather * 0.5f;
  const float overlap = kSeamOverlap * feather;
  const std::size_t n = c.size();
  out.inner.resize(n);
  out.outer.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t prev = (k + n - 1) % n;
    // Inward distances of the core's edges (outline edges move in, seams move out a little), then outward
    // distances of the ramp's outer edges.
    const float in_prev = outline[prev] ? half : -overlap, in_next = outline[k] ? half : -overlap;
    const float out_prev = outline[prev] ? half : overlap, out_next = outline[k] ? half : overlap;
    out.inner[k] = c[k] - offset_corner(normals[prev], normals[k], in_prev, in_next, max_offset);
    out.outer[k] = c[k] + offset_corner(normals[prev], normals[k], out_prev, out_next, max_offset);
  }
}

}  // namespace

void ConvexPieces::add_corner(Vec2f corner, bool outline) {
  corners_.push_back(corner);
  outline_.push_back(outline ? 1 : 0);
}

void ConvexPieces::end_piece() {
  const std::size_t begin = piece_begin(piece_ends_.size());
  // Merge repeated corners: the zero-length edge between them goes, the later corner's edge stays.
  std::size_t kept = begin;
  for (std::size_t i = begin; i < corners_.size(); ++i) {
    const bool finite = std::isfinite(corners_[i].x) && std::isfinite(corners_[i].y);
    if (!finite) continue;
    if (kept > begin && length(corners_[i] - corners_[kept - 1]) <= kSameCorner) {
      outline_[kept - 1] = outline_[i];
      continue;
    }
    corners_[kept] = corners_[i];
    outline_[kept] = outline_[i];
    ++kept;
  }
  while (kept - begin > 1 && length(corners_[kept - 1] - corners_[begin]) <= kSameCorner) --kept;
  corners_.resize(kept);
  outline_.resize(kept);
  if (kept - begin < 3) {
    corners_.resize(begin);
    outline_.resize(begin);
    return;
  }
  piece_ends_.push_back(kept);
}

void ConvexPieces::clear() {
  corners_.clear();
  outline_.clear();
  piece_ends_.clear();
}

std::span<const Vec2f> ConvexPieces::corners(std::size_t piece) const {
  const std::size_t begin = piece_begin(piece);
  return {corners_.data() + begin, piece_ends_[piece] - begin};
}

std::span<const std::uint8_t> ConvexPieces::outline(std::size_t piece) const {
  const std::size_t begin = piece_begin(piece);
  return {outline_.data() + begin, piece_ends_[piece] - begin};
}

void append_triangles(Triangles& out, const ConvexPieces& pieces) {
  for (std::size_t p = 0; p < pieces.piece_count(); ++p) {
    const auto c = pieces.corners(p);
    for (std::size_t i = 1; i + 1 < c.size(); ++i) out.insert(out.end(), {c[0], c[i], c[i + 1]});
  }
}

void append_feathered(FeatheredTriangles& out, const ConvexPieces& pieces, float feather) {
  std::vector<Vec2f> normals;
  PieceOffsets offsets;
  for (std::size_t p = 0; p < pieces.piece_count(); ++p) {  // cores
    offsets_of(pieces.corners(p), pieces.outline(p), feather, normals, offsets);
    const auto& in = offsets.inner;
    for (std::size_t i = 1; i + 1 < in.size(); ++i) out.insert(out.end(), {{in[0], 1}, {in[i], 1}, {in[i + 1], 1}});
  }
  for (std::size_t p = 0; p < pieces.piece_count(); ++p) {  // ramps
    const auto outline = pieces.outline(p);
    offsets_of(pieces.corners(p), outline, feather, normals, offsets);
    const std::size_t n = outline.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (!outline[i]) continue;
      const std::size_t j = (i + 1) % n;
      const FeatheredVertex a{offsets.inner[i], 1}, b{offsets.inner[j], 1}, c{offsets.outer[j], 0},
          d{offsets.outer[i], 0};
      out.insert(out.end(), {a, b, c, a, c, d});
    }
  }
}

}  // namespace sc
