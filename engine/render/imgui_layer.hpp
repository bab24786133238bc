#pragma once
// Dear ImGui (1.86) on top of a GlContext: owns an ImGui context, the DejaVu fonts shipped in assets/fonts/,
// the SkillCoach style, and our build of the OpenGL3 backend (which works on OSMesa, EGL and SDL alike).
// ImGui works in framebuffer pixels here (DisplayFramebufferScale = 1); fonts and sizes are scaled with the
// framebuffer height so text is equally readable at 1280x720 and at 4K.
//
// Per frame: [platform backend NewFrame + input], begin_frame(), ImGui calls, end_frame() after the scene.
#include <imgui.h>

#include <memory>
#include <optional>

#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_solid_fills.hpp"

namespace sc {

struct UiFonts {
  ImFont* body = nullptr;     // DejaVu Sans, 18 px at scale 1
  ImFont* bold = nullptr;     // DejaVu Sans Bold, 18 px
  ImFont* heading = nullptr;  // DejaVu Sans Bold, 30 px
  ImFont* title = nullptr;    // DejaVu Sans Bold, 48 px
};

class ImGuiLayer {
 public:
  // Throws InputError naming the font file when assets/fonts is missing.
  explicit ImGuiLayer(GlContext& context);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Scale for a framebuffer height: 1 at 720 px, 3 at 2160 px (clamped to [0.75, 4], in steps of 1/8 so
  // the font atlas is not rebuilt on every pixel of a window resize).
  static float scale_for_height(int framebuffer_height);

  // Keeps `scale` from now on, whatever the framebuffer's height: for an image whose height follows its content
  // (a scale that followed the height would grow the content past it).
  void hold_scale(float scale);

  // Sets the display size and time step, rebuilds fonts/style when the scale changed, calls ImGui::NewFrame().
  void begin_frame(double dt_seconds);
  // ImGui::Render() and draws it into the context's target framebuffer.
  void end_frame();

  float scale() const { return scale_; }
  const UiFonts& fonts() const { return fonts_; }
  ImGuiContext* imgui_context() const { return imgui_; }
  void make_current() const;

 private:
  void rebuild_fonts_and_style(float scale);

  GlContext& context_;
  ImGuiContext* imgui_ = nullptr;
  float scale_ = 0;
  std::optional<float> held_scale_;
  UiFonts fonts_;
  std::unique_ptr<ImGuiSolidFills> solid_fills_;
};

// The SkillCoach look: dark slate background, one blue accent, rounded widgets, generous spacing.
void apply_skillcoach_style(ImGuiStyle& style, float scale);

}  // namespace sc
