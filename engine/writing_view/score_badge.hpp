#pragma once
// Text on the writing canvas, drawn with ImGui into the background draw list (above the scene, below every
// ImGui window): the score after a trial and a caption naming the word. Call between
// ImGuiLayer::begin_frame and end_frame, with the camera used for the canvas.
//
// The score is the task's reward in [-1, 0] (engine/writing/writing_score.hpp). Like the paper ("reported
// with a positive offset"), the badge leads with points = 100 * (score + 1), which learners read more easily,
// and gives the exact score and its parts underneath.
#include <string>
#include <string_view>

#include "engine/render/camera2d.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/writing/writing_score.hpp"

namespace sc::writing_view {

// 0..100, rounded: 100 * (score + 1).
int score_points(double score);
// The score rounded to 3 decimals, without a negative zero (a perfect trace shows 0.000, not -0.000).
double rounded_score(double score);
// "87 points"
std::string score_headline(const writing::WritingScore& score);
// "score -0.134 · recall 0.91 · precision 0.95"
std::string score_details(const writing::WritingScore& score);

// A plate in the canvas's top-right corner with the headline (heading font) and the details (body font).
void draw_score_badge(const Camera2D& camera, const writing::WritingScore& score, const UiFonts& fonts);
// A caption in the canvas's top-left corner (e.g. "ab-c  ·  classic").
void draw_canvas_caption(const Camera2D& camera, std::string_view text, const UiFonts& fonts);

}  // namespace sc::writing_view
