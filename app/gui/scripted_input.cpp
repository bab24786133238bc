#include "app/gui/scripted_input.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/render/rgba_image.hpp"

namespace sc {
namespace {

constexpr int kMotionEventsPerFrame = 8;  // a drag's mouse samples per frame: a pen needs more than one
constexpr int kFirstGamepadId = 1000;     // above any real instance id of a short test run

float distance(Vec2f a, Vec2f b) { return std::hypot(b.x - a.x, b.y - a.y); }

// The point `fraction` of the way along `path` by arc length.
Vec2f along(const std::vector<Vec2f>& path, double fraction) {
  double total = 0;
  for (std::size_t i = 1; i < path.size(); ++i) total += distance(path[i - 1], path[i]);
  double left = std::clamp(fraction, 0.0, 1.0) * total;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double piece = distance(path[i - 1], path[i]);
    if (left <= piece && piece > 0) return path[i - 1] + (path[i] - path[i - 1]) * static_cast<float>(left / piece);
    left -= piece;
  }
  return path.back();
}

Uint8 sdl_button(int index) { return index == 0 ? SDL_BUTTON_LEFT : index == 1 ? SDL_BUTTON_RIGHT : SDL_BUTTON_MIDDLE; }

// Where a UTF-8 character starting at `i` ends.
std::size_t next_character(const std::string& text, std::size_t i) {
  ++i;
  while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  return i;
}

}  // namespace

ScriptedInput::ScriptedInput(InputScript script) : script_(std::move(script)) {}

void ScriptedInput::pump(const Deliver& deliver) {
  ++frame_;
  state_.time_seconds = time_of(static_cast<double>(frame_));
  SDL_Event event;
  while (SDL_PollEvent(&event))  // the real devices are not the learner here: only the window's own events
    if (event.type == SDL_QUIT || event.type == SDL_WINDOWEVENT) deliver(event);
  release_pending(deliver);
  if (drag_) continue_drag(deliver);
  while (!waiting() && next_ < script_.steps.size()) run(script_.steps[next_++], deliver);
}

bool ScriptedInput::waiting() {
  if (drag_ || frame_ < resume_frame_) return true;
  if (!until_) return false;
  const ScriptStep& step = script_.steps[*until_];
  if (screen_ == step.name) {
    until_.reset();
    return false;
  }
  if (frame_ - until_started_ > step.frames)
    fail(step, "timed out after " + std::to_string(step.frames) + " frames waiting for screen " + step.name +
                   " (showing " + screen_ + ")");
  return true;
}

void ScriptedInput::run(const ScriptStep& step, const Deliver& deliver) {
  switch (step.action) {
    case ScriptAction::wait_frames:
      resume_frame_ = frame_ + step.frames;
      break;
    case ScriptAction::until_screen:
      until_ = static_cast<std::size_t>(&step - script_.steps.data());
      until_started_ = frame_;
      break;
    case ScriptAction::expect_screen:
      if (screen_ != step.name) fail(step, "expected screen " + step.name + ", showing " + screen_);
      break;
    case ScriptAction::key:
      key(step.key, true, deliver);
      release_key_ = step.key;
      resume_frame_ = frame_ + 2;  // down this frame, up the next: ImGui sees each press as its own
      break;
    case ScriptAction::key_down:
      key(step.key, true, deliver);
      break;
    case ScriptAction::key_up:
      key(step.key, false, deliver);
      break;
    case ScriptAction::text:
      type(step.name, deliver);
      break;
    case ScriptAction::mouse_move:
      move_to(step.points[0], state_.time_seconds);
      break;
    case ScriptAction::mouse_down:
      button(step.button, true, deliver);
      break;
    case ScriptAction::mouse_up:
      button(step.button, false, deliver);
      break;
    case ScriptAction::click:
      move_to(step.points[0], state_.time_seconds);
      button(0, true, deliver);
      release_button_ = 0;
      resume_frame_ = frame_ + 2;
      break;
    case ScriptAction::drag:
      move_to(step.points[0], state_.time_seconds);
      button(0, true, deliver);
      drag_ = Drag{step.points, frame_, step.frames};
      break;
    case ScriptAction::wheel:
      wheel(step.value, deliver);
      break;
    case ScriptAction::gamepad_connect:
    case ScriptAction::gamepad_disconnect:
    case ScriptAction::gamepad_axis:
    case ScriptAction::gamepad_button:
      gamepad(step);
      break;
    case ScriptAction::screenshot:  // of this frame, before later steps change what it shows
      screenshot_ = step.name;
      resume_frame_ = frame_ + 1;
      break;
  }
}

void ScriptedInput::release_pending(const Deliver& deliver) {
  if (release_key_) key(*release_key_, false, deliver);
  if (release_button_) button(*release_button_, false, deliver);
  release_key_.reset();
  release_button_.reset();
}

// Moves the pressed mouse along the drag's path, with several motion events per frame like a real mouse,
// and lets go at the end.
void ScriptedInput::continue_drag(const Deliver& deliver) {
  const Drag& d = *drag_;
  for (int i = 1; i <= kMotionEventsPerFrame; ++i) {
    const double frame = static_cast<double>(frame_ - 1) + static_cast<double>(i) / kMotionEventsPerFrame;
    move_to(along(d.path, (frame - static_cast<double>(d.started_frame)) / d.frames), time_of(frame));
  }
  if (frame_ - d.started_frame < d.frames) return;
  button(0, false, deliver);
  drag_.reset();
  resume_frame_ = frame_ + 1;
}

void ScriptedInput::key(SDL_Scancode code, bool down, const Deliver& deliver) {
  const auto k = static_cast<std::size_t>(code);
  if (down && !state_.keys_down[k]) state_.keys_pressed[k] = true;
  state_.keys_down[k] = down;
  SDL_Event e{};
  e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.key.keysym.scancode = code;
  e.key.keysym.sym = SDL_GetKeyFromScancode(code);
  deliver(e);
}

void ScriptedInput::button(int index, bool down, const Deliver& deliver) {
  const auto i = static_cast<std::size_t>(index);
  if (down)
    state_.mouse_pressed[i] = true;
  else
    state_.mouse_released[i] = true;
  state_.mouse_down[i] = down;
  if (index == 0) state_.mouse_events.push_back({state_.time_seconds, state_.mouse_pixels, down});
  SDL_Event e{};
  e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
  e.button.button = sdl_button(index);
  e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.button.x = static_cast<int>(state_.mouse_pixels.x);
  e.button.y = static_cast<int>(state_.mouse_pixels.y);
  deliver(e);
}

void ScriptedInput::wheel(float notches, const Deliver& deliver) {
  state_.wheel += notches;
  SDL_Event e{};
  e.type = SDL_MOUSEWHEEL;
  e.wheel.y = static_cast<Sint32>(std::lround(notches));  // ImGui 1.86's backend scrolls by the sign
  e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
  deliver(e);
}

void ScriptedInput::move_to(Vec2f pixels, double time_seconds) {
  state_.mouse_inside = true;
  state_.mouse_pixels = pixels;
  state_.mouse_events.push_back({time_seconds, pixels, state_.mouse_down[0]});
}

void ScriptedInput::type(const std::string& text, const Deliver& deliver) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t end = next_character(text, i);
    SDL_Event e{};
    e.type = SDL_TEXTINPUT;
    std::memcpy(e.text.text, text.data() + i, std::min<std::size_t>(end - i, sizeof e.text.text - 1));
    deliver(e);
    i = end;
  }
}

void ScriptedInput::gamepad(const ScriptStep& step) {
  if (step.action == ScriptAction::gamepad_connect) {
    state_.gamepads.clear();
    GamepadSnapshot pad;
    pad.instance_id = kFirstGamepadId + gamepads_connected_++;  // SDL gives a re-plugged pad a new id too
    pad.name = step.name;
    state_.gamepads.push_back(pad);
    return;
  }
  if (step.action == ScriptAction::gamepad_disconnect) {
    state_.gamepads.clear();
    return;
  }
  if (state_.gamepads.empty()) fail(step, "no scripted gamepad: add {\"gamepad_connect\": \"name\"} first");
  GamepadSnapshot& pad = state_.gamepads.front();
  if (step.action == ScriptAction::gamepad_axis)
    pad.axes[static_cast<std::size_t>(step.axis)] = step.value;
  else
    pad.buttons[static_cast<std::size_t>(step.button)] = step.down;
}

// ImGui's SDL backend polls the OS mouse, which the script does not move: set what ImGui reads. A press
// counts as held for the frame it happened in, as the backend does, so a click inside one frame is seen.
void ScriptedInput::feed_imgui_mouse(float pixel_density) {
  (void)pixel_density;  // script positions are framebuffer pixels already
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = state_.mouse_inside ? ImVec2(state_.mouse_pixels.x, state_.mouse_pixels.y) : ImVec2(-FLT_MAX, -FLT_MAX);
  for (std::size_t i = 0; i < 3; ++i) io.MouseDown[i] = state_.mouse_down[i] || state_.mouse_pressed[i];
}

FrameInput ScriptedInput::poll(SDL_Window* window, float pixel_density) {
  (void)window;
  (void)pixel_density;
  FrameInput input = state_;
  state_ = state_.without_edges();
  return input;
}

void ScriptedInput::after_frame(const DrawnFrame& frame) {
  if (frame.screen != screen_) {
    screen_ = frame.screen;
    std::printf("script: frame %ld screen %s\n", frame_, screen_.c_str());
  }
  if (!screenshot_.empty()) {
    write_png(screenshot_, frame.read_pixels());
    std::printf("script: frame %ld screenshot %s\n", frame_, screenshot_.c_str());
    screenshot_.clear();
  }
  const bool idle = !drag_ && !until_ && !release_key_ && !release_button_ && frame_ >= resume_frame_;
  if (!finished_ && idle && next_ >= script_.steps.size()) {
    finished_ = true;
    std::printf("script: %s finished at frame %ld on screen %s\n", script_.file.string().c_str(), frame_,
                screen_.c_str());
  }
  std::fflush(stdout);
}

void ScriptedInput::fail(const ScriptStep& step, const std::string& problem) const {
  throw ScriptFailure(script_.file.string() + ": " + step.where + " (frame " + std::to_string(frame_) +
                      "): " + problem);
}

}  // namespace sc
