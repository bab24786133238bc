#include "engine/render/line_chart_image.hpp"

#include <algorithm>
#include <cmath>

#include "engine/render/chart_painter.hpp"

namespace sc {
namespace {

using namespace chart;

// Every point and reference line, padded by 12 % so point labels stay inside.
Range value_range(const LineChartPanel& panel) {
  Range r{INFINITY, -INFINITY};
  for (const LineSeries& l : panel.series)
    for (double v : l.y) r = {std::min(r.lo, v), std::max(r.hi, v)};
  for (const ReferenceLine& line : panel.references) r = {std::min(r.lo, line.y), std::max(r.hi, line.y)};
  if (!std::isfinite(r.lo)) r = {0.0, 1.0};
  if (r.hi - r.lo <= 0.0) r = {r.lo - 0.5, r.hi + 0.5};
  const double pad = 0.12 * (r.hi - r.lo);
  return {r.lo - pad, r.hi + pad};
}

Range x_range(const LineChartFigure& figure) {
  Range r{INFINITY, -INFINITY};
  for (const LineChartPanel& p : figure.panels)
    for (const LineSeries& l : p.series)
      for (double v : l.x) r = {std::min(r.lo, v), std::max(r.hi, v)};
  if (!std::isfinite(r.lo)) return {0.0, 1.0};
  if (r.hi - r.lo <= 0.0) r.hi = r.lo + 1.0;
  return r;
}

struct LinePainter : Painter {
  float x_of(const Range& r, const PanelBox& box, double v) const {
    return box.left + static_cast<float>((v - r.lo) / (r.hi - r.lo)) * (box.right - box.left);
  }

  void x_axis(const Range& r, const PanelBox& box, const std::string& label) {
    const double step = tick_step(r);
    line({box.left, box.bottom}, {box.right, box.bottom}, 1.5f, kAxis);
    for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-9; v += step) {
      const float x = x_of(r, box, v);
      line({x, box.bottom}, {x, box.bottom + 5 * s}, 1.0f, kAxis);
      text_centered(dl, imgui.fonts().body, 15.0f * s, {x, box.bottom + 16 * s}, kMuted, printf_value("%g", v));
    }
    text_centered(dl, imgui.fonts().bold, 16.0f * s, {(box.left + box.right) / 2, box.bottom + 40 * s}, kText, label);
  }

  void references(const LineChartPanel& panel, const Range& r, const PanelBox& box) {
    for (const ReferenceLine& ref : panel.references) {
      const float y = y_of(r, box, ref.y);
      const Vec2f ends[] = {{box.left, y}, {box.right, y}};
      renderer.dashed_polyline(ends, Stroke::pixels(2.0f), DashPattern{8 * s, 6 * s}, ref.color);
      const std::string text = ref.label + " " + printf_value(panel.value_format, ref.y);
      dl->AddText(imgui.fonts().body, 14.0f * s, {box.left + 8 * s, y - 20 * s}, kMuted, text.c_str());
    }
  }

  void series(const LineChartPanel& panel, const Range& xr, const Range& r, const PanelBox& box) {
    for (const LineSeries& l : panel.series) {
      std::vector<Vec2f> points;
      for (std::size_t i = 0; i < l.x.size() && i < l.y.size(); ++i)
        points.push_back({x_of(xr, box, l.x[i]), y_of(r, box, l.y[i])});
      if (points.size() > 1) renderer.polyline(points, Stroke::pixels(3.0f), l.color);
      // A label goes above its point, or below it when the previous label sits too close to the left.
      Vec2f last{-1e9f, -1e9f};
      for (std::size_t i = 0; i < points.size(); ++i) {
        renderer.fill_circle(points[i], 5 * s, l.color);
        Vec2f at{points[i].x, points[i].y - 14 * s};
        if (std::fabs(at.x - last.x) < 40 * s && std::fabs(at.y - last.y) < 16 * s) at.y = points[i].y + 16 * s;
        text_centered(dl, imgui.fonts().body, 13.0f * s, {at.x, at.y}, kText, printf_value(panel.value_format, l.y[i]));
        last = at;
      }
    }
  }
};

std::vector<LegendEntry> legend_of(const LineChartFigure& figure) {
  std::vector<LegendEntry> out;
  auto add = [&](const std::string& label, Color color) {
    for (const LegendEntry& e : out)
      if (e.label == label) return;
    out.push_back({label, color});
  };
  for (const LineChartPanel& p : figure.panels) {
    for (const LineSeries& l : p.series) add(l.label, l.color);
    for (const ReferenceLine& ref : p.references) add(ref.label, ref.color);
  }
  return out;
}

}  // namespace

RgbaImage render_line_chart_figure(GlContext& context, const LineChartFigure& figure) {
  const ChartFrame frame{figure.title, legend_of(figure), figure.notes, figure.width, figure.height};
  return render_chart(context, frame, [&](Painter& painter, float bottom) {
    LinePainter p{painter};
    const float s = p.s;
    const float panel_width =
        static_cast<float>(figure.width) / static_cast<float>(std::max<std::size_t>(figure.panels.size(), 1));
    const Range xr = x_range(figure);
    for (std::size_t i = 0; i < figure.panels.size(); ++i) {
      const LineChartPanel& panel = figure.panels[i];
      const PanelBox box{panel_width * static_cast<float>(i) + 80 * s, 130 * s,
                         panel_width * static_cast<float>(i + 1) - 32 * s, bottom - 76 * s};
      const Range range = value_range(panel);
      p.value_axis(panel.title, range, box);
      p.x_axis(xr, box, figure.x_label);
      p.references(panel, range, box);
      p.series(panel, xr, range, box);
    }
  });
}

}  // namespace sc
