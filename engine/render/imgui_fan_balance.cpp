#include "engine/render/imgui_fan_balance.hpp"

#include <cstddef>
#include <vector>

namespace sc {
namespace {

constexpr std::size_t kMinFanTriangles = 3;  // two triangles (a quad, a glyph) are as good as it gets

bool same_fill(const ImDrawVert& a, const ImDrawVert& b) {
  return a.col == b.col && a.uv.x == b.uv.x && a.uv.y == b.uv.y;
}

// Only a convex outline may be re-triangulated freely (a concave one drawn as a fan would change shape).
bool is_convex(const std::vector<ImDrawIdx>& outline, std::span<const ImDrawVert> vertices) {
  const std::size_t n = outline.size();
  int sign = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const ImVec2 p = vertices[outline[i]].pos, q = vertices[outline[(i + 1) % n]].pos,
                 r = vertices[outline[(i + 2) % n]].pos;
    const float cross = (q.x - p.x) * (r.y - q.y) - (q.y - p.y) * (r.x - q.x);
    const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
    if (s == 0) continue;
    if (sign == 0) sign = s;
    if (s != sign) return false;
  }
  return true;
}

// Triangles of the outline's vertices lo..hi (closed by the edge hi-lo), largest first: the triangle on the
// middle vertex, then each half. Keeps the outline's winding.
void emit_halving(const std::vector<ImDrawIdx>& outline, std::size_t lo, std::size_t hi, ImDrawIdx*& out) {
  if (hi - lo < 2) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  *out++ = outline[lo];
  *out++ = outline[mid];
  *out++ = outline[hi];
  emit_halving(outline, lo, mid, out);
  emit_halving(outline, mid, hi, out);
}

// Number of fan triangles starting at triangle `first` (of `count`).
std::size_t fan_length(std::span<const ImDrawIdx> indices, std::size_t first, std::size_t count,
                       std::span<const ImDrawVert> vertices) {
  const ImDrawIdx apex = indices[3 * first];
  if (apex >= vertices.size()) return 1;
  std::size_t k = first;
  for (; k < count; ++k) {
    const ImDrawIdx* t = &indices[3 * k];
    if (t[0] != apex || (k > first && t[1] != indices[3 * (k - 1) + 2])) break;
    if (t[1] >= vertices.size() || t[2] >= vertices.size()) break;
    if (!same_fill(vertices[apex], vertices[t[1]]) || !same_fill(vertices[apex], vertices[t[2]])) break;
  }
  return k == first ? 1 : k - first;
}

}  // namespace

void balance_convex_fans(std::span<ImDrawIdx> indices, std::span<const ImDrawVert> vertices) {
  const std::size_t triangles = indices.size() / 3;
  std::vector<ImDrawIdx> outline;
  for (std::size_t first = 0; first < triangles;) {
    const std::size_t length = fan_length(indices, first, triangles, vertices);
    if (length >= kMinFanTriangles) {
      outline.assign({indices[3 * first], indices[3 * first + 1]});
      for (std::size_t k = first; k < first + length; ++k) outline.push_back(indices[3 * k + 2]);
      if (is_convex(outline, vertices)) {
        ImDrawIdx* out = &indices[3 * first];
        emit_halving(outline, 0, outline.size() - 1, out);
      }
    }
    first += length;
  }
}

void balance_convex_fans(ImDrawData& draw_data) {
  for (int n = 0; n < draw_data.CmdListsCount; ++n) {
    ImDrawList& list = *draw_data.CmdLists[n];
    const std::span<ImDrawIdx> all_indices(list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size));
    const std::span<const ImDrawVert> all_vertices(list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      // Commands index from their own vertex offset; a fan never spans two commands.
      if (cmd.UserCallback != nullptr || cmd.VtxOffset > all_vertices.size()) continue;
      if (cmd.IdxOffset + cmd.ElemCount > all_indices.size()) continue;
      balance_convex_fans(all_indices.subspan(cmd.IdxOffset, cmd.ElemCount), all_vertices.subspan(cmd.VtxOffset));
    }
  }
}

}  // namespace sc
