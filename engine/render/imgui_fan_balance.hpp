#pragma once
// ImGui fills every convex shape (rounded window and frame backgrounds, circles) as a fan: all triangles share
// the polygon's first vertex, so a rounded panel is ~50 slivers that each cross the whole panel. A tiling
// software rasteriser (llvmpipe) shades every sliver separately in every tile it touches and never sees a
// tile it covers whole: on the review screen the panel backgrounds cost more than the lot and the text.
// This re-triangulates each such fan, in place, by halving the polygon's outline (one large triangle across
// the middle, smaller ones towards the rim). The fan's vertices share one colour and texture coordinate, and
// both triangulations cover the same convex polygon once, so the pixels are the same; only the work changes.
//
//   ImGui::Render();
//   balance_convex_fans(*ImGui::GetDrawData());
//   ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
#include <imgui.h>

#include <span>

namespace sc {

// Rewrites every run of at least 3 fan triangles in `indices` (a triangle list into `vertices`): a run is
// triangles (a, b, c), (a, c, d), (a, d, e), ... whose vertices all have a's colour and texture coordinate
// (so ImGui's anti-aliased fringe, whose outer vertices are transparent, is never part of one).
void balance_convex_fans(std::span<ImDrawIdx> indices, std::span<const ImDrawVert> vertices);

// The same for every draw list of a frame.
void balance_convex_fans(ImDrawData& draw_data);

}  // namespace sc
