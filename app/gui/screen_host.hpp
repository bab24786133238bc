#pragma once
// Runs screens on a GL context: fixed-step simulation (engine/core/fixed_step_clock), then one drawn frame of
// the scene (Renderer2D) and the UI (ImGuiLayer). The window loop and the offscreen screenshot share it, so a
// screenshot shows exactly what the window shows.
#include <string>

#include "app/gui/navigator.hpp"
#include "engine/core/fixed_step_clock.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

class ScreenHost {
 public:
  static constexpr double kSimulationStep = 1.0 / 60.0;
  static constexpr int kMaxStepsPerFrame = 8;  // beyond this a long frame is dropped (no spiral of death)

  // `max_steps_per_frame` bounds the steps of one frame: kMaxStepsPerFrame for wall-clock frames, more for
  // input scripts, whose frames are a fixed, known amount of simulation time (nothing to drop).
  ScreenHost(GlContext& context, AppServices& services, const std::string& first_screen,
             int max_steps_per_frame = kMaxStepsPerFrame);

  // Make the ImGui context current and feed platform input to ImGui (io.MousePos, ...) before calling frame().
  ImGuiLayer& imgui() { return imgui_; }
  const Renderer2D& renderer() const { return renderer_; }
  Navigator& navigator() { return navigator_; }

  // One displayed frame: `elapsed_seconds` of wall time since the previous one.
  void frame(const FrameInput& input, double elapsed_seconds);

 private:
  GlContext& context_;
  AppServices& services_;
  ImGuiLayer imgui_;
  Renderer2D renderer_;
  FixedStepClock clock_;
  Navigator navigator_;
  double screen_time_ = 0;
};

}  // namespace sc
