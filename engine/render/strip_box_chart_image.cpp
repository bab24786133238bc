#include "engine/render/strip_box_chart_image.hpp"

#include <algorithm>
#include <cmath>

#include "engine/render/chart_painter.hpp"

namespace sc {
namespace {

using namespace chart;

const Color kMeanBar = Color::hex(0x1e2126);

// Covers zero, every value, whisker and mean +- s.e., with a margin.
Range value_range(const StripBoxFigure& figure) {
  Range r{0.0, 0.0};
  auto cover = [&r](double v) {
    if (!std::isfinite(v)) return;
    r.lo = std::min(r.lo, v);
    r.hi = std::max(r.hi, v);
  };
  for (const StripBoxGroup& g : figure.groups) {
    for (double v : g.values) cover(v);
    cover(g.whisker_low);
    cover(g.whisker_high);
    if (std::isfinite(g.se)) {
      cover(g.mean - g.se);
      cover(g.mean + g.se);
    }
  }
  if (r.hi - r.lo <= 0.0) r.hi = r.lo + 1.0;
  const double pad = 0.08 * (r.hi - r.lo);
  return {r.lo - pad, r.hi + pad};
}

struct StripBoxPainter : Painter {
  void box(const StripBoxGroup& g, const Range& r, const PanelBox& panel, float left, float right) {
    if (!std::isfinite(g.q1) || !std::isfinite(g.q3)) return;
    const float mid = (left + right) / 2, y1 = y_of(r, panel, g.q1), y3 = y_of(r, panel, g.q3);
    rect(left, y1, right, y3, g.color.with_alpha(0.22f));
    line({left, y1}, {right, y1}, 2.0f, g.color);
    line({left, y3}, {right, y3}, 2.0f, g.color);
    line({left, y1}, {left, y3}, 2.0f, g.color);
    line({right, y1}, {right, y3}, 2.0f, g.color);
    if (std::isfinite(g.median)) {
      const float ym = y_of(r, panel, g.median);
      line({left, ym}, {right, ym}, 3.5f, g.color);
    }
    const float cap = (right - left) * 0.25f;
    for (auto [from, to] : {std::pair{g.q1, g.whisker_low}, std::pair{g.q3, g.whisker_high}}) {
      if (!std::isfinite(to)) continue;
      const float yf = y_of(r, panel, from), yt = y_of(r, panel, to);
      line({mid, yf}, {mid, yt}, 1.6f, g.color);
      line({mid - cap, yt}, {mid + cap, yt}, 1.6f, g.color);
    }
  }

  void points(const StripBoxGroup& g, const Range& r, const PanelBox& panel, float left, float right) {
    const float spread = (right - left) * 0.8f, mid = (left + right) / 2;
    for (std::size_t i = 0; i < g.values.size(); ++i) {
      if (!std::isfinite(g.values[i])) continue;
      // Golden-ratio sequence: evenly spread, deterministic sideways offsets.
      const double frac = std::fmod(0.5 + static_cast<double>(i) * 0.6180339887498949, 1.0);
      const float x = mid + static_cast<float>(frac - 0.5) * spread;
      const float y = y_of(r, panel, g.values[i]);
      renderer.fill_circle({x, y}, 6.0f * s, Color::hex(0xffffff));
      renderer.fill_circle({x, y}, 4.5f * s, g.color);
    }
  }

  void mean_bar(const StripBoxGroup& g, const Range& r, const PanelBox& panel, float x) {
    if (!std::isfinite(g.mean)) return;
    const float ym = y_of(r, panel, g.mean), half = 7.0f * s;
    if (std::isfinite(g.se)) {
      const float lo = y_of(r, panel, g.mean - g.se), hi = y_of(r, panel, g.mean + g.se);
      line({x, lo}, {x, hi}, 2.5f, kMeanBar);
      line({x - half, lo}, {x + half, lo}, 2.5f, kMeanBar);
      line({x - half, hi}, {x + half, hi}, 2.5f, kMeanBar);
    }
    const Vec2f diamond[] = {{x, ym - half}, {x + half, ym}, {x, ym + half}, {x - half, ym}};
    renderer.fill_polygon(diamond, kMeanBar);
  }

  void group(const StripBoxGroup& g, const Range& r, const PanelBox& panel, float x0, float width) {
    const float left = x0 + width * 0.22f, right = x0 + width * 0.62f;
    box(g, r, panel, left, right);
    points(g, r, panel, left, right);
    mean_bar(g, r, panel, x0 + width * 0.76f);
    const float centre = x0 + width * 0.5f;
    text_centered(dl, imgui.fonts().bold, 17.0f * s, {centre, panel.bottom + 22 * s}, kText, g.label);
    text_centered(dl, imgui.fonts().body, 14.0f * s, {centre, panel.bottom + 44 * s}, kMuted, g.sublabel);
  }
};

}  // namespace

RgbaImage render_strip_box_figure(GlContext& context, const StripBoxFigure& figure) {
  ChartFrame frame{figure.title, {}, figure.notes, figure.width, figure.height};
  return render_chart(context, frame, [&](Painter& painter, float bottom) {
    StripBoxPainter p{painter};
    const float s = p.s;
    const PanelBox panel{90 * s, 110 * s, static_cast<float>(figure.width) - 30 * s, bottom - 70 * s};
    const Range range = value_range(figure);
    p.value_axis(figure.panel_title, range, panel);
    const float width = (panel.right - panel.left) / static_cast<float>(std::max<std::size_t>(figure.groups.size(), 1));
    for (std::size_t i = 0; i < figure.groups.size(); ++i)
      p.group(figure.groups[i], range, panel, panel.left + width * static_cast<float>(i), width);
  });
}

}  // namespace sc
