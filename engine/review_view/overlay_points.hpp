#pragma once
// A learner's path over a reference path, in ImGui draw lists, fitted into a box: the trainer's before/after and
// hand pictures (app/gui/screens) and the report's hand picture (review_images.hpp) draw the same. Points are in
// the task's own coordinates; pictures side by side share one scale by sharing their bounds.
#include <imgui.h>

#include <cstddef>
#include <vector>

namespace sc::review_view {

inline constexpr ImU32 kOverlayLearner = IM_COL32(255, 226, 138, 235);  // the learner's path (yellow)
inline constexpr ImU32 kOverlayGuide = IM_COL32(91, 155, 255, 80);      // the expert's path or the guide (blue band)
inline constexpr ImU32 kOverlayHand = IM_COL32(120, 220, 170, 90);      // the learner's hand (green band)
inline constexpr ImU32 kOverlayPart = IM_COL32(255, 140, 66, 255);      // a part of the learner's path (orange)
// Their line widths in pixels, for the pictures and their legends alike.
inline constexpr float kOverlayLearnerWidth = 2.5f;
inline constexpr float kOverlayBandWidth = 7.0f;
inline constexpr float kOverlayPartWidth = 4.0f;

// The joint bounds of several point sets.
struct OverlayBounds {
  ImVec2 lo{1e30f, 1e30f}, hi{-1e30f, -1e30f};
  void include(const std::vector<ImVec2>& points);
};

// `points` mapped into the box at `top_left` of `size` (uniform scale, centred, a 10 px margin) by `bounds`.
std::vector<ImVec2> fit_into_box(const std::vector<ImVec2>& points, ImVec2 top_left, ImVec2 size,
                                 const OverlayBounds& bounds);

// Points at least `spacing` pixels apart (first and last kept). A writing trace has a point per pen pixel, which
// shrinks to a fraction of a pixel in a thumbnail: a thick polyline through such zigzags draws a miter spike at
// every one of them (the expert's word looked hairy), and thousands of segments per picture cost frame time.
std::vector<ImVec2> thinned(const std::vector<ImVec2>& points, float spacing);

// A thick polyline (box coordinates), split where it turns back sharply: ImGui joins segments with unlimited
// miters, which at a pen reversing its direction draw a long spike.
void draw_thick_path(ImDrawList& draw_list, const std::vector<ImVec2>& points, ImU32 color, float thickness);

// A dark box, `reference` over it as a wide band of colour `band`, `learner` over that (mapped by `bounds`).
// Nothing but the box when either path has fewer than two points.
void draw_overlay_points(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const std::vector<ImVec2>& learner,
                         const std::vector<ImVec2>& reference, const OverlayBounds& bounds, ImU32 band);

// Where a diagnosis target went wrong: the learner's trial over the expert's of the same scenario, and the
// learner's points [first, last] (the part aligned with the expert's segment) in orange over them.
struct PartOverlay {
  std::vector<ImVec2> learner, expert;
  std::size_t first = 0, last = 0;
};
void draw_part_overlay(ImDrawList& draw_list, ImVec2 top_left, ImVec2 size, const PartOverlay& overlay);

// The learner's own hand (teaching/sessions/learner_hand_traces.hpp): one pre-test trial, its guide and the
// hand taken, in the task's coordinates.
struct HandOverlay {
  std::vector<ImVec2> learner, guide, hand;
};

// Two boxes at one scale: the learner over the guide at `first`, the learner over the hand at `second`.
void draw_hand_overlay(ImDrawList& draw_list, ImVec2 first, ImVec2 second, ImVec2 box, const HandOverlay& overlay);

}  // namespace sc::review_view
