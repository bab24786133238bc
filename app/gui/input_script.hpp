#pragma once
// A script of learner input for the trainer window (`skillcoach --script FILE.json`), read into plain steps.
// The format (docs/input-script.md):
//   {"steps_per_frame": 4, "window": [1280, 720],
//    "steps": [{"until_screen": "start", "max_frames": 10}, {"click": [640, 600]}, {"text": "Ada"},
//              {"key": "Return"}, {"key_down": "Up"}, {"wait_seconds": 6}, {"key_up": "Up"},
//              {"drag": [[300, 300], [500, 320]], "frames": 30}, {"repeat": 3, "steps": [...]},
//              {"screenshot": "summary.png"}, {"expect_screen": "learn_summary"}]}
// Each step holds one action; steps run in order, several in the same frame until a step that waits
// (wait_frames, wait_seconds, until_screen, drag, screenshot, and the frame after a key or click that
// releases it).
// Positions are framebuffer pixels, top-left origin. Bad scripts throw InputError naming the file and the
// JSON path of the step.
#include <SDL.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/render/draw_types.hpp"

namespace sc {

enum class ScriptAction {
  wait_frames,    // frames
  until_screen,   // name; fails after max frames
  expect_screen,  // name; fails if another screen shows
  key,            // key down now, up the next frame
  key_down,
  key_up,
  text,        // typed text (SDL text input)
  mouse_move,  // points[0]
  mouse_down,  // button
  mouse_up,
  click,            // move to points[0], button down now, up the next frame
  drag,             // left button down along points over `frames`, then up
  wheel,            // value
  gamepad_connect,  // name
  gamepad_disconnect,
  gamepad_axis,    // axis, value
  gamepad_button,  // button, down
  screenshot,      // name = PNG path (relative to the working directory)
};

struct ScriptStep {
  ScriptAction action = ScriptAction::wait_frames;
  std::string where;  // "$.steps[3]" (for failures)
  int frames = 0;
  std::string name;
  SDL_Scancode key = SDL_SCANCODE_UNKNOWN;
  int button = 0;  // mouse: 0 left, 1 right, 2 middle; gamepad: SDL_GameControllerButton
  int axis = 0;    // SDL_GameControllerAxis
  float value = 0;
  bool down = false;
  std::vector<Vec2f> points;
};

// Half a second of simulation per drawn frame: whole sessions run in few frames (each costs a render)
// while a countdown or a demo still spans several.
inline constexpr int kMaxScriptStepsPerFrame = 30;

struct InputScript {
  std::filesystem::path file;
  int steps_per_frame = 1;  // fixed simulation steps (1/60 s each) per drawn frame, 1..kMaxScriptStepsPerFrame
  int width = 1280;         // window size in points
  int height = 720;
  std::vector<ScriptStep> steps;  // repeats expanded

  double frame_seconds() const;
};

// Throws InputError("<file>: <json path>: <problem>") for anything it cannot play.
InputScript read_input_script(const std::filesystem::path& file);

}  // namespace sc
