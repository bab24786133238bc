#pragma once
// Grouped bar charts with error bars as an image, drawn with the engine's own renderer (bars, axes) and
// ImGui (text) into an offscreen context, for figures that commands write next to their numbers
// (e.g. `skillcoach simulate-students`). Values may be negative: bars grow from zero either way.
#include <string>
#include <vector>

#include "engine/render/draw_types.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

struct BarSeries {
  std::string label;  // legend text
  Color color;
};

struct BarGroup {
  std::string label;           // under the group
  std::vector<double> values;  // one per series (NaN: no bar)
  std::vector<double> errors;  // half-length of each error bar (empty or 0: none)
};

struct BarChartPanel {
  std::string title;
  std::string value_format = "%.3f";  // printf format of the value printed at each bar's end
  std::vector<BarGroup> groups;
};

struct BarChartFigure {
  std::string title;
  std::vector<std::string> notes;  // small lines under the panels
  std::vector<BarSeries> series;
  std::vector<BarChartPanel> panels;  // side by side
  int width = 1280;
  int height = 720;
};

// Renders into `context` (resized to the figure's size). Fonts come from assets/fonts (ImGuiLayer).
RgbaImage render_bar_chart_figure(GlContext& context, const BarChartFigure& figure);

}  // namespace sc
