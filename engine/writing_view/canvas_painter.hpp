#pragma once
// Paints the writing canvas with Renderer2D in canvas pixels (set a writing_canvas_camera first). Each
// layer is a function so the free-write screen, the trainer's drills and the offscreen trial images compose
// the same pieces in the same order:
//
//   renderer.set_camera(writing_canvas_camera(viewport));
//   paint_paper(renderer);                                  // desk, paper, faint rules, start mark
//   paint_guide(renderer, gold.points());                   // the goal word, faint, underneath
//   paint_drill_ribbon(renderer, drill_points);             // a drill's path: ribbon, start dot, arrows
//   paint_ink(renderer, learner_trace);                     // the learner's ink (pen-up moves not drawn)
//   paint_ghost_pen(renderer, ghost_pen_at(gold.points(), t)); // the expert writing, at writing speed
//
// Widths are in canvas pixels (Stroke::world), so everything scales with the canvas.
#include <span>

#include "engine/render/renderer2d.hpp"
#include "engine/writing/trace_point.hpp"
#include "engine/writing_view/ghost_pen.hpp"

namespace sc::writing_view {

struct WritingCanvasLook {
  Color desk = Color::hex(0x2b2f36);   // around the paper
  Color paper = Color::hex(0xf6f1e4);  // warm off-white
  Color paper_edge = Color::hex(0xd8d0bc);
  Color rule = Color::hex(0xb9cbe0, 0.45f);     // faint ruled lines every kRuleSpacing
  Color baseline = Color::hex(0x9fb6d3, 0.8f);  // y = 150, where every word starts
  Color start_mark = Color::hex(0x6f8fb8, 0.9f);
  float rule_spacing = 50.0f;

  Color guide = Color::hex(0x8f8a80, 0.30f);  // the goal word underneath (as in the paper's interface)
  float guide_width = 7.0f;                   // about the score's full-credit band (+-3 px)
  Color ink = Color::hex(0x1b2a4e);           // the learner's pen
  float ink_width = 2.6f;

  Color ribbon = Color::hex(0x2f7de1, 0.26f);  // a drill's ghost path
  float ribbon_width = 12.0f;
  Color ribbon_hop = Color::hex(0x2f7de1, 0.55f);
  Color arrow = Color::hex(0x0f4fb0, 0.9f);
  float arrow_spacing = 45.0f;
  float arrow_length = 13.0f;
  Color start_dot = Color::hex(0x23a35a);
  float start_dot_radius = 5.5f;

  Color ghost_ink = Color::hex(0xd9622b, 0.85f);  // what the ghost pen has written so far
  float ghost_ink_width = 3.0f;
  Color ghost_hop = Color::hex(0xd9622b, 0.45f);  // its pen-up moves, as faint dashed hops
  Color ghost_tip = Color::hex(0xd9622b);
  float ghost_tip_radius = 4.5f;
};

// The desk (a fill of the whole visible world), the 500 x 300 paper with faint rules, the baseline y = 150
// and a small mark at the start position (0, 150).
void paint_paper(Renderer2D& renderer, const WritingCanvasLook& look = {});

// The goal word as faint wide ink (pen-up moves not drawn).
void paint_guide(Renderer2D& renderer, std::span<const writing::TracePoint> gold, const WritingCanvasLook& look = {});

// A trace's ink: pen-down runs as round-capped lines, taps as dots; pen-up moves are not drawn.
void paint_ink(Renderer2D& renderer, std::span<const writing::TracePoint> trace, Color color, float width);
void paint_learner_ink(Renderer2D& renderer, std::span<const writing::TracePoint> trace,
                       const WritingCanvasLook& look = {});

// Where the ink of a path begins: the start of its first pen-down segment (the path's first point when it
// has no ink). (0, 0) for an empty path.
Vec2f first_pen_down(std::span<const writing::TracePoint> path);

// A path to follow (a drill, or the whole gold word as an overlay): a translucent ribbon over its ink (even
// where it crosses itself), dashed hops for its pen-up moves, direction arrows every look.arrow_spacing and a
// dot where the pen first goes down (a full-alphabet character begins with a pen-up move from where the
// previous symbol ended: the dot marks where to start writing, the dashed hop how the pen gets there).
void paint_drill_ribbon(Renderer2D& renderer, std::span<const writing::TracePoint> path,
                        const WritingCanvasLook& look = {});

// The ghost pen: the part written so far, pen-up moves as faint dashed hops, and the pen tip (a filled dot
// while drawing, a ring while lifted).
void paint_ghost_pen(Renderer2D& renderer, const GhostPenFrame& frame, const WritingCanvasLook& look = {});

}  // namespace sc::writing_view
