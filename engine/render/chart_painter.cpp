#include "engine/render/chart_painter.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>

namespace sc::chart {

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

float Painter::y_of(const Range& r, const PanelBox& box, double v) const {
  return box.bottom - static_cast<float>((v - r.lo) / (r.hi - r.lo)) * (box.bottom - box.top);
}

void Painter::rect(float x0, float y0, float x1, float y1, Color color) {
  renderer.fill_rect({{(x0 + x1) / 2, (y0 + y1) / 2}, {std::fabs(x1 - x0) / 2, std::fabs(y1 - y0) / 2}}, color);
}

void Painter::line(Vec2f a, Vec2f b, float width, Color color) {
  const Vec2f points[] = {a, b};
  renderer.polyline(points, Stroke::pixels(width), color);
}

void Painter::value_axis(const std::string& title, const Range& r, const PanelBox& box) {
  const double step = tick_step(r);
  ImFont* font = imgui.fonts().body;
  const float size = 15.0f * s;
  for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-12; v += step) {
    const float y = y_of(r, box, v);
    line({box.left, y}, {box.right, y}, 1.0f, std::fabs(v) < step * 1e-6 ? kAxis : kGrid);
    const std::string label = printf_value(step < 0.01  ? "%.3f"
                                           : step < 0.1 ? "%.2f"
                                                        : "%.1f",
                                           std::fabs(v) < step * 1e-6 ? 0.0 : v);
    const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, label.c_str());
    dl->AddText(font, size, {box.left - extent.x - 8 * s, y - extent.y / 2}, kMuted, label.c_str());
  }
  line({box.left, box.top}, {box.left, box.bottom}, 1.5f, kAxis);
  text_centered(dl, imgui.fonts().bold, 20.0f * s, {(box.left + box.right) / 2, box.top - 28 * s}, kText, title);
}

void Painter::legend(const std::vector<LegendEntry>& entries, float y, float width) {
  ImFont* font = imgui.fonts().body;
  const float size = 16.0f * s, swatch = 14.0f * s, gap = 28.0f * s;
  float total = 0.0f;
  for (const LegendEntry& b : entries)
    total += swatch + 6 * s + font->CalcTextSizeA(size, FLT_MAX, 0.0f, b.label.c_str()).x + gap;
  float x = (width - total + gap) / 2;
  for (const LegendEntry& b : entries) {
    rect(x, y - swatch / 2, x + swatch, y + swatch / 2, b.color);
    dl->AddText(font, size, {x + swatch + 6 * s, y - size * 0.6f}, kText, b.label.c_str());
    x += swatch + 6 * s + font->CalcTextSizeA(size, FLT_MAX, 0.0f, b.label.c_str()).x + gap;
  }
}

RgbaImage render_chart(GlContext& context, const ChartFrame& frame,
                       const std::function<void(Painter&, float bottom)>& panels) {
  context.make_current();
  context.resize(frame.width, frame.height);
  Renderer2D renderer(context);
  ImGuiLayer imgui(context);
  renderer.begin_frame(kBackground);
  imgui.begin_frame(1.0 / 60.0);
  Painter p{renderer, imgui, ImGui::GetBackgroundDrawList(), imgui.scale()};
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height), s = p.s;
  text_centered(p.dl, imgui.fonts().heading, 24.0f * s, {w / 2, 26 * s}, kText, frame.title);
  p.legend(frame.legend, 62 * s, w);
  const float notes_height = static_cast<float>(frame.notes.size()) * 20.0f * s;
  panels(p, h - notes_height);
  for (std::size_t i = 0; i < frame.notes.size(); ++i)
    p.dl->AddText(imgui.fonts().body, 14.0f * s, {16 * s, h - notes_height - 8 * s + 20.0f * s * static_cast<float>(i)},
                  kMuted, frame.notes[i].c_str());
  renderer.end_frame();
  imgui.end_frame();
  context.present();
  return context.read_rgba();
}

}  // namespace sc::chart
