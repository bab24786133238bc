#pragma once
// Line charts as an image (e.g. a learning curve: reward against training epochs), drawn like the bar
// charts (bar_chart_image.hpp) with the engine's renderer and ImGui text into an offscreen context.
// Panels side by side share the x values' axis; horizontal reference lines mark levels such as an
// expert's reward.
#include <string>
#include <vector>

#include "engine/render/draw_types.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

struct LineSeries {
  std::string label;  // legend text
  Color color;
  std::vector<double> x, y;  // same length, x ascending
};

struct ReferenceLine {
  std::string label;  // legend text and a label at the line's right end
  Color color;
  double y = 0.0;
};

struct LineChartPanel {
  std::string title;
  std::string value_format = "%.3f";  // printf format of each point's label
  std::vector<LineSeries> series;
  std::vector<ReferenceLine> references;
};

struct LineChartFigure {
  std::string title;
  std::string x_label;             // under every panel
  std::vector<std::string> notes;  // small lines under the panels
  std::vector<LineChartPanel> panels;
  int width = 1280;
  int height = 720;
};

// Renders into `context` (resized to the figure's size). Fonts come from assets/fonts (ImGuiLayer).
RgbaImage render_line_chart_figure(GlContext& context, const LineChartFigure& figure);

}  // namespace sc
