#pragma once
// Where the trainer window's input comes from, swappable like a platform backend: the live source reads the
// user's devices through SDL (SdlInput), the scripted source (scripted_input.hpp) plays a JSON script of
// key presses, text, mouse and gamepad actions at given frames with a fixed frame time, so whole sessions
// can be driven through the real screens reproducibly. The window loop (gui_main.cpp) knows only this.
#include <SDL.h>

#include <functional>
#include <string>

#include "app/gui/frame_input.hpp"
#include "app/gui/sdl_input.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

// What the loop shows the source after a frame was drawn (before it is presented).
struct DrawnFrame {
  const std::string& screen;               // the navigator's current screen (after this frame's change)
  std::function<RgbaImage()> read_pixels;  // the frame just drawn
};

class InputSource {
 public:
  virtual ~InputSource() = default;
  // Collects this frame's events and hands each SDL event the window must see (ImGui, quit) to `deliver`.
  virtual void pump(const std::function<void(const SDL_Event&)>& deliver) = 0;
  // Seconds the simulation advances this frame, and the most simulation steps one frame may run.
  virtual double frame_seconds() = 0;
  virtual int max_steps_per_frame() const;
  // Called after ImGui_ImplSDL2_NewFrame: ImGui's mouse in framebuffer pixels (the backend polls SDL).
  virtual void feed_imgui_mouse(float pixel_density) = 0;
  // The frame's device snapshot for the screens; clears the edges.
  virtual FrameInput poll(SDL_Window* window, float pixel_density) = 0;
  virtual void after_frame(const DrawnFrame& frame) { (void)frame; }
  // True when the source has nothing more to give and the window should close.
  virtual bool finished() const { return false; }
};

// The user's devices: SDL events and polled state, wall-clock frame times.
class LiveInputSource final : public InputSource {
 public:
  void pump(const std::function<void(const SDL_Event&)>& deliver) override;
  double frame_seconds() override;
  void feed_imgui_mouse(float pixel_density) override;
  FrameInput poll(SDL_Window* window, float pixel_density) override;

 private:
  SdlInput input_;
  Uint64 previous_ = 0;  // performance counter at the previous frame; 0 before the first
};

}  // namespace sc
