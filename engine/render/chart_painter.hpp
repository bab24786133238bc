#pragma once
// What the figure images (bar_chart_image, line_chart_image) share: a value axis with round ticks, the
// engine renderer's rectangles and lines, ImGui text, and a centred legend. Internal to engine/render.
#include <functional>
#include <string>
#include <vector>

#include <imgui.h>

#include "engine/render/draw_types.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc::chart {

inline const Color kBackground = Color::hex(0xffffff);
inline const Color kAxis = Color::hex(0x3a3f47);
inline const Color kGrid = Color::hex(0xe3e6ea);
inline constexpr ImU32 kText = IM_COL32(30, 33, 38, 255);
inline constexpr ImU32 kMuted = IM_COL32(95, 102, 112, 255);

struct Range {
  double lo = 0.0, hi = 1.0;
};

// 1, 2 or 5 times a power of ten, giving about five ticks.
double tick_step(const Range& r);
std::string printf_value(const std::string& fmt, double v);
void text_centered(ImDrawList* dl, ImFont* font, float size, ImVec2 center, ImU32 color, const std::string& text);

struct PanelBox {
  float left, top, right, bottom;  // the plot area in pixels
};

struct LegendEntry {
  std::string label;
  Color color;
};

struct Painter {
  Renderer2D& renderer;
  const ImGuiLayer& imgui;
  ImDrawList* dl;
  float s;  // ImGui scale

  float y_of(const Range& r, const PanelBox& box, double v) const;
  void rect(float x0, float y0, float x1, float y1, Color color);
  void line(Vec2f a, Vec2f b, float width, Color color);
  // Grid lines and tick labels of the value axis, the axis line, the panel title above the box.
  void value_axis(const std::string& title, const Range& r, const PanelBox& box);
  // A row of colour swatches and labels centred at height y.
  void legend(const std::vector<LegendEntry>& entries, float y, float width);
};

struct ChartFrame {
  std::string title;
  std::vector<LegendEntry> legend;
  std::vector<std::string> notes;  // small lines at the bottom
  int width = 1280;
  int height = 720;
};

// One figure: resizes `context`, draws the title, the legend and the notes, and calls
// panels(painter, bottom) to draw the panels between the legend and `bottom` (pixels, above the notes).
RgbaImage render_chart(GlContext& context, const ChartFrame& frame,
                       const std::function<void(Painter&, float bottom)>& panels);

}  // namespace sc::chart
