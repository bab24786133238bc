#pragma once
// A strip plot over box plots as an image: per group every value as a point (spread sideways by a fixed
// low-discrepancy sequence, so the picture is the same on every run), the box of its quartiles with the
// median and whiskers, and the mean +- standard error as a black bar beside the box. Drawn like the other
// figures (chart_painter.hpp) with the engine's renderer and ImGui text into an offscreen context. The
// caller computes the statistics (teaching/stats/sample_summary.hpp); NaN leaves a part out.
#include <string>
#include <vector>

#include "engine/render/draw_types.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

struct StripBoxGroup {
  std::string label;     // under the group, bold
  std::string sublabel;  // under the label (e.g. "N = 20")
  Color color;
  std::vector<double> values;
  double q1 = 0.0, median = 0.0, q3 = 0.0;       // the box (NaN: no box)
  double whisker_low = 0.0, whisker_high = 0.0;  // the whiskers' ends
  double mean = 0.0, se = 0.0;                   // the black bar (NaN mean: none; NaN se: the mean only)
};

struct StripBoxFigure {
  std::string title;
  std::string panel_title;  // above the plot area (what the values are)
  std::vector<std::string> notes;
  std::vector<StripBoxGroup> groups;
  int width = 1280;
  int height = 720;
};

// Renders into `context` (resized to the figure's size). The value axis always includes zero.
RgbaImage render_strip_box_figure(GlContext& context, const StripBoxFigure& figure);

}  // namespace sc
