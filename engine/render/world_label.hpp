#pragma once
// Text anchored to a point of the scene, drawn with ImGui over the renderer's output (into the background
// draw list, so it sits above the scene and below every ImGui window). Call between ImGuiLayer::begin_frame
// and end_frame, with the camera used for the scene.
#include <imgui.h>

#include <string_view>

#include "engine/render/camera2d.hpp"
#include "engine/render/draw_types.hpp"

namespace sc {

enum class LabelAnchor { center, above, below, left, right };

struct LabelStyle {
  Color color = Color::hex(0xffffff);
  LabelAnchor anchor = LabelAnchor::center;
  float offset_pixels = 6;              // gap between the point and the text for non-centre anchors
  ImFont* font = nullptr;               // nullptr: the current ImGui font
  Color background = Color::hex(0, 0);  // alpha > 0 draws a rounded plate behind the text
};

void draw_world_label(const Camera2D& camera, Vec2f world, std::string_view text, const LabelStyle& style = {},
                      ImDrawList* draw_list = nullptr);

}  // namespace sc
