#pragma once
// Builds FrameInput from SDL in the window: keeps the connected game controllers (hot-plug: devices added or
// removed mid-session appear/disappear), tracks mouse and key edges from events, and polls device state once
// per frame.
#include <SDL.h>

#include <vector>

#include "app/gui/frame_input.hpp"

namespace sc {

class SdlInput {
 public:
  SdlInput();  // opens the controllers already connected (SDL_INIT_GAMECONTROLLER must be initialised)
  ~SdlInput();
  SdlInput(const SdlInput&) = delete;
  SdlInput& operator=(const SdlInput&) = delete;

  void handle_event(const SDL_Event& event);
  // The frame's input; `pixel_density` converts window points to framebuffer pixels. Clears the edges.
  FrameInput poll(SDL_Window* window, float pixel_density);

 private:
  void open_controller(int device_index);
  void close_controller(SDL_JoystickID instance_id);

  std::vector<SDL_GameController*> controllers_;
  FrameInput edges_;  // pressed/released/wheel accumulated since the last poll
};

}  // namespace sc
