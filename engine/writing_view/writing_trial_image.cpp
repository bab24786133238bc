#include "engine/writing_view/writing_trial_image.hpp"

#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/writing_view/canvas_geometry.hpp"

namespace sc::writing_view {
namespace {

// ImGui lays out its first frame differently from later ones (stack notes §3), so the capture is frame 2.
constexpr int kFrames = 2;

}  // namespace

RgbaImage render_writing_scene_image(const WritingScene& scene, int width, int height) {
  auto context = create_offscreen_context_from_env(width, height);
  ImGuiLayer imgui(*context);
  Renderer2D renderer(*context);
  const WritingCanvasLook look;
  for (int frame = 0; frame < kFrames; ++frame) {
    imgui.make_current();
    imgui.begin_frame(1.0 / 60.0);
    renderer.begin_frame(look.desk);
    const Camera2D camera = writing_canvas_camera(
        {0.0f, 0.0f, static_cast<float>(context->width()), static_cast<float>(context->height())});
    renderer.set_camera(camera);
    paint_writing_scene(renderer, scene, look);
    draw_writing_scene_text(camera, scene, imgui.fonts());
    renderer.end_frame();
    imgui.end_frame();
    context->present();
  }
  return context->read_rgba();
}

WritingScene writing_trial_scene(const writing::WritingTrial& trial, const WritingRenderOptions& options) {
  const writing::WordTrajectory gold = options.data_dir.empty()
                                           ? writing::gold_trajectory(trial.scenario)
                                           : writing::gold_trajectory(trial.scenario, options.data_dir);
  const std::vector<writing::TracePoint> gold_points = gold.points();
  WritingScene scene;
  if (options.show_guide) scene.guide = gold_points;
  if (options.overlay_expert) scene.ribbon = gold_points;
  scene.learner = trial.points;
  if (options.show_score && !trial.points.empty()) scene.score = writing::score_writing(gold_points, trial.points);
  scene.caption = trial.scenario.word + "  \xc2\xb7  " + std::string(writing::alphabet_name(trial.scenario.alphabet));
  if (!trial.source.empty()) scene.caption += "  \xc2\xb7  " + trial.source;
  if (!trial.device.empty()) scene.caption += " (" + trial.device + ")";
  return scene;
}

RgbaImage render_writing_trial_image(const writing::WritingTrial& trial, const WritingRenderOptions& options) {
  return render_writing_scene_image(writing_trial_scene(trial, options), options.width, options.height);
}

void render_writing_trial_png(const writing::WritingTrial& trial, const WritingRenderOptions& options,
                              const std::filesystem::path& out) {
  write_png(out, render_writing_trial_image(trial, options));
}

}  // namespace sc::writing_view
