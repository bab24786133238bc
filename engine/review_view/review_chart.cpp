#include "engine/review_view/review_chart.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/review_view/review_palette.hpp"

namespace sc::review_view {
namespace {

constexpr ImU32 kText = IM_COL32(230, 234, 240, 255);
constexpr ImU32 kMuted = IM_COL32(150, 160, 175, 255);
constexpr ImU32 kGrid = IM_COL32(70, 78, 92, 255);
constexpr ImU32 kPanel = IM_COL32(24, 29, 38, 255);

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

std::string skill_title(const ChartSkill& s) { return "skill " + std::to_string(s.skill) + ": " + s.label; }

// Skill names of models one trains oneself run to ~85 characters: a title wraps within the chart, never clips.
float title_wrap_width(float chart_width, float scale) {
  return std::max(1.0f, chart_width - 28.0f * scale - ImGui::GetFontSize() * 1.1f);
}

ImFont* title_font(ImFont* bold) { return bold ? bold : ImGui::GetFont(); }

float title_height(ImFont* bold, float wrap, const ChartSkill& s) {
  return title_font(bold)->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, wrap, skill_title(s).c_str()).y;
}

float titles_height(const ExpertiseChart& chart, ImFont* bold, float wrap) {
  float sum = 0.0f;
  for (const ChartSkill& s : chart.skills) sum += title_height(bold, wrap, s);
  return sum;
}

}  // namespace

// The least height of one round's bar: 14 px at scale 1, and never less than its value label's line, or the labels
// of several rounds overlap.
float least_bar(float scale) { return std::max(14.0f * scale, ImGui::GetFontSize()); }

float expertise_chart_height(const ExpertiseChart& chart, float scale, float width, ImFont* bold) {
  const float bars = least_bar(scale) * static_cast<float>(std::max<std::size_t>(1, chart.rounds.size()));
  return ImGui::GetFontSize() * 3.5f + titles_height(chart, bold, title_wrap_width(width, scale)) +
         (18.0f * scale + bars) * static_cast<float>(chart.skills.size()) + 2 * 14.0f * scale;  // the panel's pads
}

void draw_expertise_chart(ImDrawList& dl, ImVec2 p, ImVec2 size, const ExpertiseChart& chart, float scale,
                          ImFont* bold) {
  const float fs = ImGui::GetFontSize();
  // Bars share the height the chart was given (between 14 and 40 px at scale 1), so a chart of a few skills
  // fills its box instead of leaving it empty.
  const float pad = 14.0f * scale;
  const float rows = static_cast<float>(std::max<std::size_t>(1, chart.skills.size()));
  const float bars = rows * static_cast<float>(std::max<std::size_t>(1, chart.rounds.size()));
  const float wrap = title_wrap_width(size.x, scale);
  const float fixed = fs * 3.5f + titles_height(chart, bold, wrap) + rows * 18.0f * scale + pad;
  const float bar = std::clamp((size.y - fixed) / bars, least_bar(scale), std::max(least_bar(scale), 40.0f * scale));
  dl.AddRectFilled(p, {p.x + size.x, p.y + std::min(size.y, fixed + bars * bar + pad)}, kPanel, 8.0f * scale);
  const float left = p.x + pad, right = p.x + size.x - pad - 150.0f * scale;  // room for "-0.28   drilled"
  float y = p.y + pad * 0.6f;
  // Legend: one shade per round (later rounds brighter), and what the outline means.
  float x = left;
  for (std::size_t r = 0; r < chart.rounds.size(); ++r) {
    const float a = 0.45f + 0.55f * static_cast<float>(r + 1) / static_cast<float>(chart.rounds.size());
    dl.AddRectFilled({x, y + fs * 0.2f}, {x + fs * 0.9f, y + fs * 0.9f},
                     IM_COL32(200, 205, 215, static_cast<int>(255 * a)), 2.0f);
    dl.AddText({x + fs * 1.2f, y}, kMuted, chart.rounds[r].c_str());
    x += fs * 1.2f + ImGui::CalcTextSize(chart.rounds[r].c_str()).x + fs;
  }
  dl.AddRect({x, y + fs * 0.15f}, {x + fs * 0.9f, y + fs * 0.95f}, IM_COL32(255, 255, 255, 255), 2.0f, 0, 2.0f * scale);
  dl.AddText({x + fs * 1.2f, y}, kMuted, "drilled in that round");
  y += fs * 1.3f;
  dl.AddText({left, y}, kMuted, "longer bar = weaker (E = -sum of the deltas)");
  y += fs * 1.6f;
  const double full = chart.lowest < 0.0 ? -chart.lowest : 1.0;
  for (const ChartSkill& s : chart.skills) {
    dl.AddRectFilled({left, y + fs * 0.15f}, {left + fs * 0.8f, y + fs * 0.95f}, chart.palette.color_u32(s.skill),
                     3.0f);
    dl.AddText(title_font(bold), fs, {left + fs * 1.1f, y}, kText, skill_title(s).c_str(), nullptr, wrap);
    y += title_height(bold, wrap, s) + 6.0f * scale;
    dl.AddLine({left, y - 2.0f * scale}, {left, y + bar * static_cast<float>(s.values.size())}, kGrid, 1.0f);
    for (std::size_t r = 0; r < s.values.size(); ++r) {
      const float a = 0.45f + 0.55f * static_cast<float>(r + 1) / static_cast<float>(s.values.size());
      const float top = y + 2.0f * scale, bottom = y + bar - 2.0f * scale;
      if (s.values[r]) {
        const float length = static_cast<float>(-*s.values[r] / full) * (right - left);
        const float end = left + std::max(length, 2.0f * scale);
        dl.AddRectFilled({left, top}, {end, bottom}, chart.palette.color_u32(s.skill, a), 2.0f);
        if (r < s.drilled.size() && s.drilled[r])
          dl.AddRect({left - 1.0f, top - 1.0f}, {end + 1.0f, bottom + 1.0f}, IM_COL32(255, 255, 255, 255), 2.0f, 0,
                     2.0f * scale);
        const bool drilled = r < s.drilled.size() && s.drilled[r];
        const std::string value = number(*s.values[r]) + (drilled ? "   drilled" : "");
        dl.AddText({end + 6.0f * scale, y + (bar - fs) * 0.5f}, drilled ? kText : kMuted, value.c_str());
      } else {
        dl.AddText({left + 6.0f * scale, y + (bar - fs) * 0.5f}, kMuted, "not used by the expert this round");
      }
      y += bar;
    }
    y += 12.0f * scale;
  }
}

void draw_reward_plot(ImDrawList& dl, ImVec2 p, ImVec2 size, const RewardPlot& plot, float scale) {
  const float fs = ImGui::GetFontSize();
  dl.AddRectFilled(p, {p.x + size.x, p.y + size.y}, kPanel, 8.0f * scale);
  dl.AddText({p.x + 10.0f * scale, p.y + 6.0f * scale}, kMuted, plot.caption.c_str());
  const float left = p.x + 58.0f * scale, right = p.x + size.x - 12.0f * scale;
  const float top = p.y + fs + 14.0f * scale, bottom = p.y + size.y - fs - 10.0f * scale;
  if (plot.rewards.empty() || right <= left || bottom <= top) return;
  double lowest = 0.0;
  for (double r : plot.rewards) lowest = std::min(lowest, r);
  if (lowest >= 0.0) lowest = -1.0;
  const double t_end = std::max(plot.times.back(), 1e-6);
  auto to_px = [&](double t, double r) {
    return ImVec2(left + static_cast<float>(t / t_end) * (right - left),
                  top + static_cast<float>(r / lowest) * (bottom - top));
  };
  dl.AddLine({left, top}, {right, top}, kGrid, 1.0f);
  dl.AddLine({left, bottom}, {right, bottom}, kGrid, 1.0f);
  dl.AddText({p.x + 8.0f * scale, top - fs * 0.5f}, kMuted, "0");
  dl.AddText({p.x + 8.0f * scale, bottom - fs * 0.5f}, kMuted, number(lowest).c_str());
  char end_label[32];
  std::snprintf(end_label, sizeof end_label, "%.1f s", t_end);
  dl.AddText({right - ImGui::CalcTextSize(end_label).x, bottom + 2.0f * scale}, kMuted, end_label);
  dl.AddText({left, bottom + 2.0f * scale}, kMuted, "0 s");
  std::vector<ImVec2> points;
  for (std::size_t i = 0; i < plot.rewards.size() && i < plot.times.size(); ++i)
    points.push_back(to_px(plot.times[i], plot.rewards[i]));
  dl.AddPolyline(points.data(), static_cast<int>(points.size()), IM_COL32(255, 226, 138, 255), 0, 2.5f * scale);
  if (plot.playhead) {
    const float x = left + static_cast<float>(std::clamp(*plot.playhead / t_end, 0.0, 1.0)) * (right - left);
    dl.AddLine({x, top}, {x, bottom}, IM_COL32(255, 255, 255, 200), 2.0f * scale);
  }
}

}  // namespace sc::review_view
