#include "engine/render/imgui_fan_balance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace sc {
namespace {

constexpr ImU32 kFill = IM_COL32(27, 32, 41, 255);
const ImVec2 kFanWhiteUv{0.125f, 0.0078125f};

ImDrawVert vertex(float x, float y, ImU32 col = kFill) { return {{x, y}, kFanWhiteUv, col}; }

// A regular polygon of `n` corners (convex), as ImGui's fan: (0, i, i + 1).
std::vector<ImDrawVert> polygon(int n) {
  std::vector<ImDrawVert> v;
  for (int i = 0; i < n; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(n);
    v.push_back(vertex(100 + 80 * std::cos(a), 100 + 80 * std::sin(a)));
  }
  return v;
}

std::vector<ImDrawIdx> fan(int n) {
  std::vector<ImDrawIdx> idx;
  for (int i = 1; i + 1 < n; ++i) idx.insert(idx.end(), {0, static_cast<ImDrawIdx>(i), static_cast<ImDrawIdx>(i + 1)});
  return idx;
}

float signed_area(const std::vector<ImDrawVert>& v, const ImDrawIdx* t) {
  const ImVec2 a = v[t[0]].pos, b = v[t[1]].pos, c = v[t[2]].pos;
  return 0.5f * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

int triangles_on_vertex(const std::vector<ImDrawIdx>& idx, ImDrawIdx vertex_index) {
  int count = 0;
  for (std::size_t i = 0; i < idx.size(); i += 3)
    count += (idx[i] == vertex_index || idx[i + 1] == vertex_index || idx[i + 2] == vertex_index) ? 1 : 0;
  return count;
}

TEST(ImGuiFanBalance, ConvexFanBecomesBalancedTriangulationOfTheSamePolygon) {
  const int n = 48;
  const auto v = polygon(n);
  const auto before = fan(n);
  auto after = before;
  balance_convex_fans(after, v);
  ASSERT_EQ(after.size(), before.size());
  float area_before = 0, area_after = 0;
  for (std::size_t i = 0; i < before.size(); i += 3) {
    area_before += signed_area(v, &before[i]);
    const float a = signed_area(v, &after[i]);
    EXPECT_GT(a, 0.0f) << "triangle " << i / 3 << " flipped or degenerate";  // same winding as the fan
    area_after += a;
  }
  EXPECT_NEAR(area_after, area_before, 1e-3f * area_before);
  // Every corner is still used, and no vertex carries a long fan of slivers any more (46 before).
  EXPECT_EQ(std::set<ImDrawIdx>(after.begin(), after.end()).size(), static_cast<std::size_t>(n));
  EXPECT_EQ(triangles_on_vertex(before, 0), n - 2);
  for (ImDrawIdx k = 0; k < n; ++k) EXPECT_LE(triangles_on_vertex(after, k), 12) << "vertex " << k;  // 2 log2 n
}

TEST(ImGuiFanBalance, StopsAtAVertexOfAnotherColourSuchAsTheAntiAliasedFringe) {
  auto v = polygon(8);
  v.push_back(vertex(190, 100, IM_COL32(27, 32, 41, 0)));  // a transparent outer fringe vertex
  auto idx = fan(8);
  const std::vector<ImDrawIdx> fringe{0, 7, 8};  // continues the fan's index pattern, but is not fill
  idx.insert(idx.end(), fringe.begin(), fringe.end());
  balance_convex_fans(idx, v);
  EXPECT_EQ(std::vector<ImDrawIdx>(idx.end() - 3, idx.end()), fringe);
  EXPECT_LE(triangles_on_vertex(std::vector<ImDrawIdx>(idx.begin(), idx.end() - 3), 0), 3);
}

TEST(ImGuiFanBalance, LeavesQuadsAndConcaveFansAlone) {
  const std::vector<ImDrawVert> quad{vertex(0, 0), vertex(10, 0), vertex(10, 10), vertex(0, 10)};
  std::vector<ImDrawIdx> quad_idx{0, 1, 2, 0, 2, 3};
  balance_convex_fans(quad_idx, quad);
  EXPECT_EQ(quad_idx, (std::vector<ImDrawIdx>{0, 1, 2, 0, 2, 3}));

  // An arrow-like outline with a notch: drawn as a fan it has a definite shape, which must not change.
  const std::vector<ImDrawVert> concave{vertex(0, 0), vertex(10, 0), vertex(10, 10), vertex(5, 3), vertex(0, 10)};
  const std::vector<ImDrawIdx> concave_idx{0, 1, 2, 0, 2, 3, 0, 3, 4};
  auto kept = concave_idx;
  balance_convex_fans(kept, concave);
  EXPECT_EQ(kept, concave_idx);
}

}  // namespace
}  // namespace sc
