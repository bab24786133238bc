#include "engine/render/world_label.hpp"

#include <cmath>

namespace sc {

void draw_world_label(const Camera2D& camera, Vec2f world, std::string_view text, const LabelStyle& style,
                      ImDrawList* draw_list) {
  ImDrawList* list = draw_list != nullptr ? draw_list : ImGui::GetBackgroundDrawList();
  ImFont* font = style.font != nullptr ? style.font : ImGui::GetFont();
  const float size = font->FontSize;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0, begin, end);
  const Vec2f p = camera.world_to_pixel(world);
  const float gap = style.offset_pixels;
  ImVec2 top_left(p.x - extent.x * 0.5f, p.y - extent.y * 0.5f);
  switch (style.anchor) {
    case LabelAnchor::center:
      break;
    case LabelAnchor::above:
      top_left.y = p.y - gap - extent.y;
      break;
    case LabelAnchor::below:
      top_left.y = p.y + gap;
      break;
    case LabelAnchor::left:
      top_left.x = p.x - gap - extent.x;
      break;
    case LabelAnchor::right:
      top_left.x = p.x + gap;
      break;
  }
  // Whole pixels keep glyphs crisp (the atlas is rasterised for pixel-aligned drawing).
  top_left = ImVec2(std::floor(top_left.x), std::floor(top_left.y));
  if (style.background.a > 0) {
    const float pad = size * 0.25f;
    list->AddRectFilled(ImVec2(top_left.x - pad, top_left.y - pad * 0.5f),
                        ImVec2(top_left.x + extent.x + pad, top_left.y + extent.y + pad * 0.5f),
                        style.background.packed_abgr(), pad);
  }
  list->AddText(font, size, top_left, style.color.packed_abgr(), begin, end);
}

}  // namespace sc
