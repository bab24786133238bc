#pragma once
// The review's charts, drawn into an ImGui draw list (so the app's screens and the offscreen report images
// draw exactly the same): per-skill expertise across rounds as horizontal bars (longer = weaker, the
// trainer's diagnosis convention), and a trial's reward over time with an optional playhead.
// Call between ImGui NewFrame and Render (the fonts and the font size come from the current frame).
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "engine/review_view/review_palette.hpp"

namespace sc::review_view {

struct ChartSkill {
  int skill = 0;
  std::string label;                          // "reversing while turning right"
  std::vector<std::optional<double>> values;  // E_m (<= 0) per round; empty: no evidence that round
  std::vector<bool> drilled;                  // per round: practised in a played drill or skill item
};

struct ExpertiseChart {
  std::vector<std::string> rounds;  // "round 1", ...
  std::vector<ChartSkill> skills;
  double lowest = 0.0;   // the most negative value (the bars' full length)
  SkillPalette palette;  // the session's skill colours
};

struct RewardPlot {
  std::vector<double> times;       // seconds
  std::vector<double> rewards;     // <= 0, 0 best
  std::optional<double> playhead;  // seconds
  std::string caption;             // e.g. "reward after each control step"
};

// The height the chart needs at `scale` (1 at 720 px) and `width` (skill titles wrap within it; `bold` is the
// font they are drawn in), to size a scroll region or an image.
float expertise_chart_height(const ExpertiseChart& chart, float scale, float width, ImFont* bold);
void draw_expertise_chart(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const ExpertiseChart& chart, float scale,
                          ImFont* bold);
void draw_reward_plot(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const RewardPlot& plot, float scale);

}  // namespace sc::review_view
