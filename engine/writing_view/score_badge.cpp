#include "engine/writing_view/score_badge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/writing_view/canvas_geometry.hpp"

namespace sc::writing_view {
namespace {

constexpr float kInsetWorld = 8.0f;  // canvas pixels between the canvas corner and the plate

ImVec2 text_size(ImFont* font, std::string_view text) {
  return font->CalcTextSizeA(font->FontSize, 1e9f, 0.0f, text.data(), text.data() + text.size());
}

}  // namespace

int score_points(double score) { return static_cast<int>(std::lround(100.0 * (std::clamp(score, -1.0, 0.0) + 1.0))); }

double rounded_score(double score) { return std::round(score * 1000.0) / 1000.0 + 0.0; }

std::string score_headline(const writing::WritingScore& score) {
  const int points = score_points(score.score);
  return std::to_string(points) + (points == 1 ? " point" : " points");
}

std::string score_details(const writing::WritingScore& score) {
  char text[128];
  std::snprintf(text, sizeof text, "score %.3f \xc2\xb7 recall %.2f \xc2\xb7 precision %.2f",
                rounded_score(score.score), score.recall, score.precision);
  return text;
}

void draw_score_badge(const Camera2D& camera, const writing::WritingScore& score, const UiFonts& fonts) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const std::string headline = score_headline(score);
  const std::string details = score_details(score);
  const ImVec2 head_size = text_size(fonts.heading, headline);
  const ImVec2 detail_size = text_size(fonts.body, details);
  const float pad = fonts.body->FontSize * 0.5f;
  const float width = std::max(head_size.x, detail_size.x) + 2.0f * pad;
  const float height = head_size.y + detail_size.y + 2.0f * pad;
  const WorldRect canvas = canvas_rect();
  const Vec2f corner = camera.world_to_pixel({canvas.max_x - kInsetWorld, canvas.min_y + kInsetWorld});
  const ImVec2 top_left(std::floor(corner.x - width), std::floor(corner.y));
  const ImVec2 bottom_right(top_left.x + width, top_left.y + height);
  list->AddRectFilled(top_left, bottom_right, Color::hex(0x1b2a4e, 0.88f).packed_abgr(), pad);
  // Green for a good trial, amber in the middle, red for a poor one: the colour alone tells how it went.
  const int points = score_points(score.score);
  const Color accent = points >= 80 ? Color::hex(0x6fdc8c) : points >= 50 ? Color::hex(0xf2c14e) : Color::hex(0xff7b72);
  list->AddText(fonts.heading, fonts.heading->FontSize, ImVec2(top_left.x + pad, top_left.y + pad),
                accent.packed_abgr(), headline.c_str());
  list->AddText(fonts.body, fonts.body->FontSize, ImVec2(top_left.x + pad, top_left.y + pad + head_size.y),
                Color::hex(0xdfe6f2).packed_abgr(), details.c_str());
}

void draw_canvas_caption(const Camera2D& camera, std::string_view text, const UiFonts& fonts) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const WorldRect canvas = canvas_rect();
  const Vec2f corner = camera.world_to_pixel({canvas.min_x + kInsetWorld, canvas.min_y + kInsetWorld});
  list->AddText(fonts.bold, fonts.bold->FontSize, ImVec2(std::floor(corner.x), std::floor(corner.y)),
                Color::hex(0x5a6477).packed_abgr(), text.data(), text.data() + text.size());
}

}  // namespace sc::writing_view
