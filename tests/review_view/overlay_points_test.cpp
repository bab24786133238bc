// The learner-over-reference drawing (engine/review_view/overlay_points.hpp) as ImGui vertices: everything stays
// inside its box, and a path that turns back on itself draws no miter spike beyond the line's own width (the
// report's hand picture showed long spikes where a pen reversed).
#include "engine/review_view/overlay_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace sc::review_view {
namespace {

class OverlayPoints : public ::testing::Test {
 protected:
  // One real frame (default font atlas built, so the lines are drawn as the app draws them: anti-aliased,
  // mitred joins), drawing into the background list.
  void SetUp() override {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(400, 400);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    ImGui::NewFrame();
    list_ = ImGui::GetBackgroundDrawList();
  }
  void TearDown() override {
    ImGui::EndFrame();
    ImGui::DestroyContext(context_);
  }
  // The bounds of the vertices drawn in colour `col` (the lines' cores; their anti-aliased fringes fade to
  // transparent, the box is another colour).
  ImVec4 drawn_bounds(ImU32 col) const {
    ImVec4 b(1e30f, 1e30f, -1e30f, -1e30f);
    for (const ImDrawVert& v : list_->VtxBuffer)
      if (v.col == col)
        b = ImVec4(std::min(b.x, v.pos.x), std::min(b.y, v.pos.y), std::max(b.z, v.pos.x), std::max(b.w, v.pos.y));
    return b;
  }
  ImGuiContext* context_ = nullptr;
  ImDrawList* list_ = nullptr;
};

TEST(Thinned, KeepsBothEndsAndNoTwoPointsCloserThanTheSpacing) {
  std::vector<ImVec2> dense;  // a pen trace with a point every 0.2 px, shrunk into a thumbnail
  for (int i = 0; i <= 500; ++i) dense.emplace_back(0.2f * i, 0.1f * (i % 7));
  const std::vector<ImVec2> thin = thinned(dense, 1.5f);
  ASSERT_GE(thin.size(), 2u);
  EXPECT_LT(thin.size(), dense.size() / 5);
  EXPECT_EQ(thin.front().x, dense.front().x);
  EXPECT_EQ(thin.back().x, dense.back().x);
  for (std::size_t i = 1; i + 1 < thin.size(); ++i)
    EXPECT_GE(std::hypot(thin[i].x - thin[i - 1].x, thin[i].y - thin[i - 1].y), 1.5f) << i;
  const std::vector<ImVec2> short_path = thinned({{3, 4}, {3.5f, 4}}, 1.5f);  // shorter than the spacing
  ASSERT_EQ(short_path.size(), 2u);
  EXPECT_EQ(short_path.back().x, 3.5f);
  EXPECT_TRUE(thinned({}, 1.5f).empty());
}

TEST_F(OverlayPoints, BoundsHoldEveryPointOfEverySet) {
  OverlayBounds b;
  b.include({{1, 5}, {3, -2}});
  b.include({{-4, 0}});
  EXPECT_EQ(b.lo.x, -4.0f);
  EXPECT_EQ(b.lo.y, -2.0f);
  EXPECT_EQ(b.hi.x, 3.0f);
  EXPECT_EQ(b.hi.y, 5.0f);
}

TEST_F(OverlayPoints, APathThatTurnsBackDrawsNoSpikeOutsideItsWidth) {
  // Right, then straight back left a little lower: a hairpin, as a pen retracing a stroke.
  const std::vector<ImVec2> hairpin{{0, 0}, {100, 0}, {0, 4}};
  const std::vector<ImVec2> learner{{0, 0}, {50, 2}};
  OverlayBounds bounds;
  bounds.include(hairpin);
  const ImVec2 top_left(0, 0), size(220, 120);
  draw_overlay_points(*list_, top_left, size, learner, hairpin, bounds, kOverlayGuide);
  const ImVec4 drawn = drawn_bounds(kOverlayGuide);
  // The mapped hairpin spans x in [10, 210]; a 7 px band's core may reach 3.5 px beyond its ends.
  // ImGui's unlimited miter at the turn reached far past the box's right edge.
  EXPECT_LE(drawn.z, 210.0f + 4.0f);
  EXPECT_GE(drawn.x, 10.0f - 4.0f);
}

TEST_F(OverlayPoints, TheHandPictureDrawsBothBoxesAtOneScale) {
  HandOverlay overlay{{{0, 0}, {10, 0}}, {{0, 0}, {10, 0}}, {{0, 0}, {20, 0}}};
  draw_hand_overlay(*list_, {0, 0}, {0, 200}, {220, 100}, overlay);
  // The learner's end (x = 10 of 0..20) lands at the middle of both boxes: one scale for all three paths.
  float first_end = -1.0f, second_end = -1.0f;
  for (const ImDrawVert& v : list_->VtxBuffer) {
    if (v.col != kOverlayLearner) continue;
    float& end = v.pos.y < 100 ? first_end : second_end;
    end = std::max(end, v.pos.x);
  }
  EXPECT_NEAR(first_end, second_end, 0.5f);
  EXPECT_LT(first_end, 140.0f);  // the learner's 10 of 20 does not fill the 220 px box
}

TEST_F(OverlayPoints, ThePartOverlayDrawsOnlyThePartInOrangeAtTheWholeTrialsScale) {
  // The learner along x = 0..40, the expert to x = 80; the part is the learner's points 2..4 (x = 20..40).
  PartOverlay overlay{{{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}}, {{0, 0}, {80, 0}}, 2, 4};
  draw_part_overlay(*list_, {0, 0}, {180, 100}, overlay);
  // 80 units over 160 px (a 10 px margin each side): the part spans x = 50..90 px, its 4 px core 2 px beyond.
  const ImVec4 part = drawn_bounds(kOverlayPart);
  EXPECT_NEAR(part.x, 50.0f, 2.5f);
  EXPECT_NEAR(part.z, 90.0f, 2.5f);
  // No part, no orange: an empty range or one past the learner's points.
  for (const auto& [first, last] : {std::pair<std::size_t, std::size_t>{3, 3}, {2, 9}}) {
    list_->_ResetForNewFrame();
    overlay.first = first;
    overlay.last = last;
    draw_part_overlay(*list_, {0, 0}, {180, 100}, overlay);
    EXPECT_GT(drawn_bounds(kOverlayPart).x, drawn_bounds(kOverlayPart).z) << first << ".." << last;
  }
}

}  // namespace
}  // namespace sc::review_view
