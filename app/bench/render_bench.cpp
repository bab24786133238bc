// Rendering at the trainer's default window size (1280x720), offscreen on the machine's GL (llvmpipe on a
// headless box: the CPU rasterises, so this is the worst case a learner's laptop would see). Each frame
// ends with glFinish so the time includes the rasterisation, not just the command submission.
//  * render/frame_1280x720/<screen>: one whole app frame (scene + ImGui + present) of a screen as the
//    screenshot command shows it (label: the screen and the GL backend):
//      free_drive    the free-drive screen, its simulation advancing one step per frame;
//      learn_trial   a parking practice trial being driven, the expert's ghost path over the lot;
//      review_trial  the instructor's trial viewer (trail, ghost ribbon, skill markers, charts);
//      learn_diagnosis, learn_diagnosis_writing_hand13  the diagnosis page (a picture of each skill and of where
//                    it went wrong; writing: in drawer 13's hand, so the hand's two pictures as well).
//    The trial and review screens are timed with the clock held (no simulation step), so every iteration
//    draws the same frame however many iterations the library runs;
//  * render/renderer2d_lot_scene_1280x720: Renderer2D alone on a parking-lot-like scene (30 spot
//    outlines, 14 parked cars, a 300-point trail, a translucent 100-point ghost ribbon, goal arrow).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "app/gui/app_services.hpp"
#include "app/gui/frame_input.hpp"
#include "app/gui/navigator.hpp"
#include "app/gui/screen_host.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/renderer2d.hpp"

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

std::unique_ptr<sc::GlContext> offscreen_context(benchmark::State& state) {
  try {
    return sc::create_offscreen_context_from_env(kWidth, kHeight);
  } catch (const sc::InputError& e) {
    state.SkipWithError(e.what());
    return nullptr;
  }
}

void BM_ScreenFrame(benchmark::State& state, const char* screen, bool advance_clock,
                    sc::TaskKind task = sc::TaskKind::parking, int learner_hand = 0) {
  auto context = offscreen_context(state);
  if (!context) return;
  if (!sc::Navigator::is_available(screen)) {
    state.SkipWithError((std::string("screen ") + screen + " is not in this build").c_str());
    return;
  }
  sc::AppServices services;
  services.headless = true;
  services.task = task;
  services.screenshot_learner_hand = learner_hand;
  if (task == sc::TaskKind::writing) services.device.kind = sc::DeviceKind::mouse_pen;
  sc::ScreenHost host(*context, services, screen);
  const sc::FrameInput input;
  for (int warmup = 0; warmup < 3; ++warmup) {  // ImGui's first frames differ (window sizes settle)
    host.imgui().make_current();
    host.frame(input, sc::ScreenHost::kSimulationStep);
    context->present();
  }
  const double elapsed = advance_clock ? sc::ScreenHost::kSimulationStep : 0.0;
  for (auto _ : state) {
    host.imgui().make_current();
    host.frame(input, elapsed);
    context->present();
    context->gl().Finish();
  }
  state.SetLabel(std::string(screen) + " screen, " + std::string(context->backend_name()));
  // The scene's share (ImGui's triangles are not counted): on llvmpipe each triangle has a set-up cost.
  state.counters["scene_draw_calls"] = host.renderer().last_frame_stats().draw_calls;
  state.counters["scene_vertices"] = host.renderer().last_frame_stats().vertices;
  // 1 when the static lot was copied from its cache rather than drawn (Renderer2D::begin_static_layer).
  state.counters["static_layer_copies"] = host.renderer().last_frame_stats().static_layer_copies;
}
BENCHMARK_CAPTURE(BM_ScreenFrame, free_drive, "free_drive", true)
    ->Name("render/frame_1280x720/free_drive")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ScreenFrame, learn_trial, "learn_trial", false)
    ->Name("render/frame_1280x720/learn_trial")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ScreenFrame, review_trial, "review_trial", false)
    ->Name("render/frame_1280x720/review_trial")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ScreenFrame, learn_diagnosis, "learn_diagnosis", false)
    ->Name("render/frame_1280x720/learn_diagnosis")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ScreenFrame, learn_diagnosis_writing, "learn_diagnosis", false, sc::TaskKind::writing, 13)
    ->Name("render/frame_1280x720/learn_diagnosis_writing_hand13")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A lot seen from above, world units = metres, like the parking view.
void draw_lot_scene(sc::Renderer2D& r, const std::vector<sc::Vec2f>& trail, const std::vector<sc::Vec2f>& ghost) {
  r.begin_frame(sc::Color::hex(0x20242c));
  r.set_camera(sc::Camera2D({-32, -18, 32, 18}, {0, 0, kWidth, kHeight}, sc::WorldYAxis::down));
  r.fill_rect({{0, 0}, {30, 16}, 0}, sc::Color::hex(0x3a3f47));
  for (int k = 0; k < 30; ++k) {
    const float x = -27.0f + 3.6f * static_cast<float>(k % 15);
    const float y = k < 15 ? -12.0f : 12.0f;
    r.outline_rect({{x, y}, {1.4f, 2.6f}, 0}, sc::Stroke::pixels(2), sc::Color::hex(0xe8e8e8));
    if (k % 2 == 0 && k != 4)
      r.fill_rect({{x, y}, {1.0f, 2.2f}, 0.02f * static_cast<float>(k)}, sc::Color::hex(0x8a8f99));
  }
  r.polyline(trail, sc::Stroke::pixels(3), sc::Color::hex(0xf2c94c));
  r.ghost_ribbon(ghost, sc::Stroke::world(2.0f), sc::Color::hex(0x2f80ed, 0.35f));
  r.fill_rect({{trail.back().x, trail.back().y}, {1.0f, 2.2f}, 0.4f}, sc::Color::hex(0x3d7be0));
  r.arrow({-12.6f, -6}, {-12.6f, -10}, sc::Stroke::pixels(3), {}, sc::Color::hex(0x27ae60));
  r.fill_circle({0, 0}, 0.5f, sc::Color::hex(0xeb5757));
  r.end_frame();
}

void BM_Renderer2DLotScene(benchmark::State& state) {
  auto context = offscreen_context(state);
  if (!context) return;
  std::vector<sc::Vec2f> trail, ghost;
  for (int i = 0; i < 300; ++i) {
    const float t = static_cast<float>(i) / 300.0f;
    trail.push_back({-20.0f + 8.0f * t, 8.0f * std::sin(3.0f * t) - 4.0f * t});
  }
  for (int i = 0; i < 100; ++i) {
    const float t = static_cast<float>(i) / 100.0f;
    ghost.push_back({-20.0f + 7.4f * t, 8.0f * std::cos(2.0f * t) - 14.0f * t * t});
  }
  sc::Renderer2D renderer(*context);
  draw_lot_scene(renderer, trail, ghost);  // the first frame compiles llvmpipe's shader variants
  context->present();
  context->gl().Finish();
  for (auto _ : state) {
    draw_lot_scene(renderer, trail, ghost);
    context->present();
    context->gl().Finish();
  }
  state.counters["draw_calls"] = renderer.last_frame_stats().draw_calls;
  state.counters["vertices"] = renderer.last_frame_stats().vertices;
}
BENCHMARK(BM_Renderer2DLotScene)
    ->Name("render/renderer2d_lot_scene_1280x720")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
