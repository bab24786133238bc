#include "engine/render/bar_chart_image.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {
namespace {

const Color kBackground = Color::hex(0xffffff);
const Color kAxis = Color::hex(0x3a3f47);
const Color kGrid = Color::hex(0xe3e6ea);
const ImU32 kText = IM_COL32(30, 33, 38, 255);
const ImU32 kMuted = IM_COL32(95, 102, 112, 255);

struct Range {
  double lo = 0.0, hi = 1.0;
};

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

// 1, 2 or 5 times a power of ten, giving about five ticks.
double tick_step(const Range& r) {
  const double raw = (r.hi - r.lo) / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

std::string printf_value(const std::string& fmt, double v) {
  char text[64];
  std::snprintf(text, sizeof text, fmt.c_str(), v);
  return text;
}

void text_centered(ImDrawList* dl, ImFont* font, float size, ImVec2 center, ImU32 color, const std::string& text) {
  const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str());
  dl->AddText(font, size, {center.x - extent.x / 2, center.y - extent.y / 2}, color, text.c_str());
}

struct PanelBox {
  float left, top, right, bottom;  // the plot area in pixels
};

struct Painter {
  Renderer2D& renderer;
  const ImGuiLayer& imgui;
  ImDrawList* dl;
  float s;  // ImGui scale

  float y_of(const Range& r, const PanelBox& box, double v) const {
    return box.bottom - static_cast<float>((v - r.lo) / (r.hi - r.lo)) * (box.bottom - box.top);
  }

  void rect(float x0, float y0, float x1, float y1, Color color) {
    renderer.fill_rect({{(x0 + x1) / 2, (y0 + y1) / 2}, {std::fabs(x1 - x0) / 2, std::fabs(y1 - y0) / 2}}, color);
  }
  void line(Vec2f a, Vec2f b, float width, Color color) {
    const Vec2f points[] = {a, b};
    renderer.polyline(points, Stroke::pixels(width), color);
  }

  void axes(const BarChartPanel& panel, const Range& r, const PanelBox& box) {
    const double step = tick_step(r);
    ImFont* font = imgui.fonts().body;
    const float size = 15.0f * s;
    for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-12; v += step) {
      const float y = y_of(r, box, v);
      line({box.left, y}, {box.right, y}, 1.0f, std::fabs(v) < step * 1e-6 ? kAxis : kGrid);
      const std::string label = printf_value(step < 0.01 ? "%.3f" : step < 0.1 ? "%.2f" : "%.1f", std::fabs(v) < step * 1e-6 ? 0.0 : v);
      const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, label.c_str());
      dl->AddText(font, size, {box.left - extent.x - 8 * s, y - extent.y / 2}, kMuted, label.c_str());
    }
    line({box.left, box.top}, {box.left, box.bottom}, 1.5f, kAxis);
    text_centered(dl, imgui.fonts().bold, 20.0f * s, {(box.left + box.right) / 2, box.top - 28 * s}, kText, panel.title);
  }

  void bars(const BarChartPanel& panel, const std::vector<BarSeries>& series, const Range& r, const PanelBox& box) {
    const float group_width = (box.right - box.left) / static_cast<float>(std::max<std::size_t>(panel.groups.size(), 1));
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
      text_centered(dl, imgui.fonts().bold, 17.0f * s, {box.left + group_width * (static_cast<float>(g) + 0.5f), box.bottom + 22 * s},
                    kText, group.label);
    }
  }

  void legend(const std::vector<BarSeries>& series, float y, float width) {
    ImFont* font = imgui.fonts().body;
    const float size = 16.0f * s, swatch = 14.0f * s, gap = 28.0f * s;
    float total = 0.0f;
    for (const BarSeries& b : series) total += swatch + 6 * s + font->CalcTextSizeA(size, FLT_MAX, 0.0f, b.label.c_str()).x + gap;
    float x = (width - total + gap) / 2;
    for (const BarSeries& b : series) {
      rect(x, y - swatch / 2, x + swatch, y + swatch / 2, b.color);
      dl->AddText(font, size, {x + swatch + 6 * s, y - size * 0.6f}, kText, b.label.c_str());
      x += swatch + 6 * s + font->CalcTextSizeA(size, FLT_MAX, 0.0f, b.label.c_str()).x + gap;
    }
  }
};

}  // namespace

RgbaImage render_bar_chart_figure(GlContext& context, const BarChartFigure& figure) {
  context.make_current();
  context.resize(figure.width, figure.height);
  Renderer2D renderer(context);
  ImGuiLayer imgui(context);
  renderer.begin_frame(kBackground);
  imgui.begin_frame(1.0 / 60.0);
  Painter p{renderer, imgui, ImGui::GetBackgroundDrawList(), imgui.scale()};
  const float w = static_cast<float>(figure.width), h = static_cast<float>(figure.height), s = p.s;
  text_centered(p.dl, imgui.fonts().heading, 24.0f * s, {w / 2, 26 * s}, kText, figure.title);
  p.legend(figure.series, 62 * s, w);
  const float notes_height = static_cast<float>(figure.notes.size()) * 20.0f * s;
  const float panel_width = w / static_cast<float>(std::max<std::size_t>(figure.panels.size(), 1));
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const BarChartPanel& panel = figure.panels[i];
    const PanelBox box{panel_width * static_cast<float>(i) + 80 * s, 130 * s, panel_width * static_cast<float>(i + 1) - 24 * s,
                       h - 56 * s - notes_height};
    const Range range = value_range(panel);
    p.axes(panel, range, box);
    p.bars(panel, figure.series, range, box);
  }
  for (std::size_t i = 0; i < figure.notes.size(); ++i)
    p.dl->AddText(imgui.fonts().body, 14.0f * s, {16 * s, h - notes_height - 8 * s + 20.0f * s * static_cast<float>(i)}, kMuted,
                  figure.notes[i].c_str());
  renderer.end_frame();
  imgui.end_frame();
  context.present();
  return context.read_rgba();
}

}  // namespace sc
