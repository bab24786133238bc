#include "engine/writing_view/writing_scene.hpp"

#include "engine/writing_view/score_badge.hpp"

namespace sc::writing_view {

void paint_writing_scene(Renderer2D& renderer, const WritingScene& scene, const WritingCanvasLook& look) {
  paint_paper(renderer, look);
  if (!scene.guide.empty()) paint_guide(renderer, scene.guide, look);
  if (!scene.ribbon.empty()) paint_drill_ribbon(renderer, scene.ribbon, look);
  if (!scene.learner.empty()) paint_learner_ink(renderer, scene.learner, look);
  if (scene.ghost_pen) paint_ghost_pen(renderer, *scene.ghost_pen, look);
}

void draw_writing_scene_text(const Camera2D& camera, const WritingScene& scene, const UiFonts& fonts) {
  if (!scene.caption.empty()) draw_canvas_caption(camera, scene.caption, fonts);
  if (scene.score) draw_score_badge(camera, *scene.score, fonts);
}

}  // namespace sc::writing_view
