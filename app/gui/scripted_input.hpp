#pragma once
// The scripted input source: plays an InputScript (input_script.hpp) into the real window loop. Each frame
// it runs the script's due steps, turns them into the SDL events ImGui's backend reads (keys, text, mouse
// buttons, wheel) and into its own device state (held keys, mouse position and buttons, a virtual gamepad),
// because pushed events never reach SDL's polled state (SDL_GetKeyboardState, SDL_GetMouseState) — which
// the offscreen video driver does not have anyway. Frames advance a fixed time, so a run is reproducible.
// It prints one line per screen change ("script: frame 42 screen learn_trial") and a last line with the
// screen it ended on; a failed expectation (until_screen timed out, expect_screen) throws ScriptFailure.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/gui/input_script.hpp"
#include "app/gui/input_source.hpp"

namespace sc {

class ScriptFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ScriptedInput final : public InputSource {
 public:
  explicit ScriptedInput(InputScript script);

  void pump(const std::function<void(const SDL_Event&)>& deliver) override;
  double frame_seconds() override { return script_.frame_seconds(); }
  int max_steps_per_frame() const override { return script_.steps_per_frame; }
  void feed_imgui_mouse(float pixel_density) override;
  FrameInput poll(SDL_Window* window, float pixel_density) override;
  void after_frame(const DrawnFrame& frame) override;
  bool finished() const override { return finished_; }

 private:
  using Deliver = std::function<void(const SDL_Event&)>;
  struct Drag {
    std::vector<Vec2f> path;
    long started_frame = 0;
    int frames = 1;
  };

  double time_of(double frame) const { return frame * script_.frame_seconds(); }
  bool waiting();
  void run(const ScriptStep& step, const Deliver& deliver);
  void release_pending(const Deliver& deliver);
  void continue_drag(const Deliver& deliver);
  void key(SDL_Scancode key, bool down, const Deliver& deliver);
  void button(int index, bool down, const Deliver& deliver);
  void wheel(float notches, const Deliver& deliver);
  void move_to(Vec2f pixels, double time_seconds);
  void type(const std::string& text, const Deliver& deliver);
  void gamepad(const ScriptStep& step);
  [[noreturn]] void fail(const ScriptStep& step, const std::string& problem) const;

  InputScript script_;
  std::size_t next_ = 0;              // the next step to run
  long frame_ = 0;                    // frames pumped so far
  long resume_frame_ = 0;             // steps wait until this frame
  std::optional<std::size_t> until_;  // the until_screen step being waited on
  long until_started_ = 0;
  std::optional<Drag> drag_;
  std::optional<SDL_Scancode> release_key_;  // pressed by a "key" step, released the next frame
  std::optional<int> release_button_;        // pressed by a "click" step
  std::string screen_;                       // the screen shown after the last drawn frame
  std::string screenshot_;                   // PNG to write after this frame, if any
  FrameInput state_;                         // held state, plus this frame's edges and events
  int gamepads_connected_ = 0;
  bool finished_ = false;
};

}  // namespace sc
