#include "engine/render/imgui_solid_fills.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sc {
namespace {

const ImVec2 kSolidWhiteUv{0.125f, 0.0078125f};
constexpr ImU32 kColor = IM_COL32(255, 255, 255, 255);

// Triangle list of axis-aligned squares (two triangles each); `textured` squares sample the font atlas.
struct Squares {
  std::vector<ImDrawVert> vertices;
  std::vector<ImDrawIdx> indices;
  void add(float x, float y, float side, bool textured) {
    const ImVec2 uv = textured ? ImVec2(0.5f, 0.5f) : kSolidWhiteUv;
    const auto base = static_cast<ImDrawIdx>(vertices.size());
    for (const ImVec2 p : {ImVec2(x, y), ImVec2(x + side, y), ImVec2(x + side, y + side), ImVec2(x, y + side)})
      vertices.push_back({p, uv, kColor});
    for (const int k : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<ImDrawIdx>(base + k));
  }
};

TEST(ImGuiSolidRuns, LargeRunsOfWhiteTexelTrianglesBetweenTexturedOnes) {
  Squares s;
  s.add(0, 0, 300, false);   // a panel background: 2 triangles, 90000 px
  s.add(10, 10, 20, false);  // a frame on it, same run
  s.add(12, 12, 8, true);    // a glyph: ends the run
  s.add(40, 40, 20, false);  // a small frame alone: 400 px, stays in the textured draw
  s.add(70, 70, 9, true);
  s.add(0, 400, 100, false);  // another large fill, at the end
  const auto runs = solid_runs(s.indices, s.vertices, kSolidWhiteUv);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].count, 12u);
  EXPECT_EQ(runs[1].first, 30u);
  EXPECT_EQ(runs[1].count, 6u);
}

TEST(ImGuiSolidRuns, ThresholdIsTheRunsTotalArea) {
  Squares s;
  for (int i = 0; i < 20; ++i) s.add(static_cast<float>(i) * 20, 0, 15, false);  // 20 x 225 px = 4500 px
  EXPECT_EQ(solid_runs(s.indices, s.vertices, kSolidWhiteUv, 4096.0f).size(), 1u);
  EXPECT_TRUE(solid_runs(s.indices, s.vertices, kSolidWhiteUv, 5000.0f).empty());
  EXPECT_TRUE(solid_runs(s.indices, s.vertices, ImVec2(0.5f, 0.5f)).empty());  // another white texel: none solid
}

}  // namespace
}  // namespace sc
