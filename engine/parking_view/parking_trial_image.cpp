#include "engine/parking_view/parking_trial_image.hpp"

#include <cstdio>
#include <numeric>

#include "engine/parking_view/parking_scene.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {
namespace {

void draw_caption(const ImGuiLayer& imgui, const std::string& outcome, bool with_expert) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float s = imgui.scale();
  const ImVec2 origin(14.0f * s, 12.0f * s);
  const float line = ImGui::GetFontSize() * 1.35f;
  dl->AddRectFilled({origin.x - 8 * s, origin.y - 6 * s},
                    {origin.x + 560 * s, origin.y + line * (with_expert ? 3.0f : 2.0f) + 2 * s},
                    IM_COL32(12, 15, 20, 170), 8 * s);
  dl->AddText(imgui.fonts().bold, ImGui::GetFontSize(), origin, IM_COL32(255, 255, 255, 255), outcome.c_str());
  dl->AddText({origin.x, origin.y + line}, IM_COL32(255, 226, 138, 255), "yellow line: the trial's path");
  if (with_expert)
    dl->AddText({origin.x, origin.y + 2 * line}, IM_COL32(185, 214, 255, 255),
                "ribbon: the expert's plan (blue forward, pink reversing)");
}

}  // namespace

std::string describe_parking_outcome(const ParkingPath& path) {
  const double total = std::accumulate(path.rewards.begin(), path.rewards.end(), 0.0);
  char text[160];
  if (path.success_step > 0)
    std::snprintf(text, sizeof text, "parked at step %d (%.1f s), return %.2f", path.success_step,
                  path.success_step / static_cast<double>(parking::kControlHz), total);
  else
    std::snprintf(text, sizeof text, "not parked after %d steps, return %.2f%s", path.control_steps, total,
                  path.collision ? ", collision" : "");
  return text;
}

RgbaImage render_parking_trial_image(GlContext& context, const ParkingTrial& trial,
                                     const ParkingTrialImageOptions& options) {
  context.make_current();
  context.resize(options.width, options.height);
  const ParkingPath path = simulate_parking_path(trial);
  const std::vector<Vec2f> trail = path_points(path);
  const ParkingLayout layout = make_layout(trial.scenario);
  ParkingSceneView view;
  view.layout = &layout;
  view.goal = goal_pose(trial.scenario);
  view.reverse_in = trial.scenario.reverse_in;
  view.car = car_pose_of(path.samples.back().vehicle, path.samples.back().steering);
  view.trail = trail;
  view.ghost_path = options.expert;

  Renderer2D renderer(context);
  renderer.begin_frame(Color::hex(0x14181f));
  const PixelViewport viewport{0, 0, static_cast<float>(options.width), static_cast<float>(options.height)};
  renderer.set_camera(parking_scene_camera(view, CameraMode::whole_lot, viewport));
  paint_parking_scene(renderer, view);
  renderer.end_frame();
  if (options.caption) {
    ImGuiLayer imgui(context);
    imgui.begin_frame(1.0 / 60.0);
    draw_caption(imgui, describe_parking_outcome(path), options.expert != nullptr);
    imgui.end_frame();
  }
  context.present();
  return context.read_rgba();
}

}  // namespace sc
