#include "engine/render/bar_chart_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/render/chart_painter.hpp"

namespace sc {
namespace {

using namespace chart;

// Covers zero and every bar with its error bar, padded so labels at the bar ends stay inside.
Range value_range(const BarChartPanel& panel) {
  Range r{0.0, 0.0};
  for (const BarGroup& g : panel.groups)
    for (std::size_t i = 0; i < g.values.size(); ++i) {
      if (std::isnan(g.values[i])) continue;
      const double e = i < g.errors.size() ? std::fabs(g.errors[i]) : 0.0;
      r.lo = std::min(r.lo, g.values[i] - e);
      r.hi = std::max(r.hi, g.values[i] + e);
    }
  if (r.hi - r.lo <= 0.0) r.hi = r.lo + 1.0;
  const double pad = 0.12 * (r.hi - r.lo);
  if (r.lo < 0.0) r.lo -= pad;
  if (r.hi > 0.0) r.hi += pad;
  return r;
}

struct BarPainter : Painter {
  void bars(const BarChartPanel& panel, const std::vector<BarSeries>& series, const Range& r, const PanelBox& box) {
    const float group_width =
        (box.right - box.left) / static_cast<float>(std::max<std::size_t>(panel.groups.size(), 1));
    const float bar_width = 0.8f * group_width / static_cast<float>(std::max<std::size_t>(series.size(), 1));
    const float zero = y_of(r, box, 0.0);
    for (std::size_t g = 0; g < panel.groups.size(); ++g) {
      const BarGroup& group = panel.groups[g];
      const float x0 = box.left + group_width * (static_cast<float>(g) + 0.1f);
      for (std::size_t i = 0; i < group.values.size() && i < series.size(); ++i) {
        const double v = group.values[i];
        if (std::isnan(v)) continue;
        const float left = x0 + bar_width * static_cast<float>(i), right = left + bar_width * 0.9f;
        const float mid = (left + right) / 2, end = y_of(r, box, v);
        rect(left, zero, right, end, series[i].color);
        const double e = i < group.errors.size() ? std::fabs(group.errors[i]) : 0.0;
        if (e > 0.0) {
          const float y_lo = y_of(r, box, v - e), y_hi = y_of(r, box, v + e), cap = bar_width * 0.18f;
          line({mid, y_lo}, {mid, y_hi}, 1.6f, kAxis);
          line({mid - cap, y_lo}, {mid + cap, y_lo}, 1.6f, kAxis);
          line({mid - cap, y_hi}, {mid + cap, y_hi}, 1.6f, kAxis);
        }
        // The value just beyond the error bar's far end.
        const float label_y = v < 0 ? y_of(r, box, v - e) + 10 * s : y_of(r, box, v + e) - 10 * s;
        text_centered(dl, imgui.fonts().body, 13.0f * s, {mid, label_y}, kText, printf_value(panel.value_format, v));
      }
      text_centered(dl, imgui.fonts().bold, 17.0f * s,
                    {box.left + group_width * (static_cast<float>(g) + 0.5f), box.bottom + 22 * s}, kText, group.label);
    }
  }
};

}  // namespace

RgbaImage render_bar_chart_figure(GlContext& context, const BarChartFigure& figure) {
  ChartFrame frame{figure.title, {}, figure.notes, figure.width, figure.height};
  for (const BarSeries& b : figure.series) frame.legend.push_back({b.label, b.color});
  return render_chart(context, frame, [&](Painter& painter, float bottom) {
    BarPainter p{painter};
    const float s = p.s;
    const float panel_width =
        static_cast<float>(figure.width) / static_cast<float>(std::max<std::size_t>(figure.panels.size(), 1));
    for (std::size_t i = 0; i < figure.panels.size(); ++i) {
      const BarChartPanel& panel = figure.panels[i];
      const PanelBox box{panel_width * static_cast<float>(i) + 80 * s, 130 * s,
                         panel_width * static_cast<float>(i + 1) - 24 * s, bottom - 56 * s};
      const Range range = value_range(panel);
      p.value_axis(panel.title, range, box);
      p.bars(panel, figure.series, range, box);
    }
  });
}

}  // namespace sc
