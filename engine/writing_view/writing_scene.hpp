#pragma once
// Everything one view of the writing canvas may show, as data, and how it is drawn: the free-write screen,
// the trainer's drills and the offscreen trial images all fill a WritingScene and call these two functions,
// so they look the same everywhere.
#include <optional>
#include <string>
#include <vector>

#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/writing/writing_score.hpp"
#include "engine/writing_view/canvas_painter.hpp"
#include "engine/writing_view/ghost_pen.hpp"

namespace sc::writing_view {

struct WritingScene {
  std::vector<writing::TracePoint> guide;    // the goal word, faint underneath (usually the gold's points)
  std::vector<writing::TracePoint> ribbon;   // a path to follow: a drill, or the gold as an overlay
  std::vector<writing::TracePoint> learner;  // the learner's ink
  std::optional<GhostPenFrame> ghost_pen;    // the expert writing (ghost_pen_at)
  std::optional<writing::WritingScore> score;
  std::string caption;  // top-left, e.g. "ab-c  ·  classic"
};

// Paints, in this order: paper, guide, ribbon, learner ink, ghost pen. Call after setting a camera made by
// writing_canvas_camera (the desk fills whatever the camera shows).
void paint_writing_scene(Renderer2D& renderer, const WritingScene& scene, const WritingCanvasLook& look = {});
// The caption and score badge (ImGui; between ImGuiLayer::begin_frame and end_frame).
void draw_writing_scene_text(const Camera2D& camera, const WritingScene& scene, const UiFonts& fonts);

}  // namespace sc::writing_view
