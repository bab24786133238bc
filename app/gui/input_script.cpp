#include "app/gui/input_script.hpp"

#include <array>
#include <cmath>
#include <string_view>
#include <utility>

#include "app/gui/screen_host.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"

namespace sc {
namespace {

constexpr int kMaxRepeat = 1000;
constexpr int kMaxFrames = 1000000;
constexpr std::size_t kMaxExpandedSteps = 200000;  // a typo in nested repeats must not eat the memory
// Nesting is read recursively and each level's JSON path is longer, so depth is bounded (scripts use 1-2
// levels); and repeats of empty or small bodies are bounded by the work they expand to, counting every
// pass through a list of steps, not only the steps kept (1000^3 empty passes never add a step). A repeat's
// body is read once and its steps copied: reading it again per pass made that work JSON parsing (about a
// second for 2,000,000 passes in a Release build, over libFuzzer's 10 s under the sanitizers).
constexpr int kMaxRepeatDepth = 16;
constexpr std::size_t kMaxExpansionWork = 2000000;

struct ActionName {
  std::string_view key;
  ScriptAction action;
};

constexpr std::array<ActionName, 18> kActions{{
    {"wait_frames", ScriptAction::wait_frames},
    {"until_screen", ScriptAction::until_screen},
    {"expect_screen", ScriptAction::expect_screen},
    {"key", ScriptAction::key},
    {"key_down", ScriptAction::key_down},
    {"key_up", ScriptAction::key_up},
    {"text", ScriptAction::text},
    {"mouse_move", ScriptAction::mouse_move},
    {"mouse_down", ScriptAction::mouse_down},
    {"mouse_up", ScriptAction::mouse_up},
    {"click", ScriptAction::click},
    {"drag", ScriptAction::drag},
    {"wheel", ScriptAction::wheel},
    {"gamepad_connect", ScriptAction::gamepad_connect},
    {"gamepad_disconnect", ScriptAction::gamepad_disconnect},
    {"gamepad_axis", ScriptAction::gamepad_axis},
    {"gamepad_button", ScriptAction::gamepad_button},
    {"screenshot", ScriptAction::screenshot},
}};

// Members that qualify an action rather than being one.
bool is_modifier(std::string_view key) {
  return key == "comment" || key == "max_frames" || key == "frames" || key == "value" || key == "down" ||
         key == "steps";
}

std::string action_list() {
  std::string list = "wait_seconds, repeat";
  for (const auto& a : kActions) list += ", " + std::string(a.key);
  return list;
}

int int_in(const JsonView& v, long long lo, long long hi) {
  const long long n = v.integer();
  if (n < lo || n > hi) v.fail("expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<int>(n);
}

int frames_of(const JsonView& v) { return int_in(v, 0, kMaxFrames); }

Vec2f point_of(const JsonView& v) {
  if (!v.is_array() || v.size() != 2) v.fail("expected a position [x, y] in pixels");
  return {static_cast<float>(v.at(std::size_t{0}).number_in(-1e5, 1e5)),
          static_cast<float>(v.at(std::size_t{1}).number_in(-1e5, 1e5))};
}

SDL_Scancode key_of(const JsonView& v) {
  const SDL_Scancode key = SDL_GetScancodeFromName(v.string().c_str());
  if (key == SDL_SCANCODE_UNKNOWN)
    v.fail("unknown key name (SDL scancode names: \"Return\", \"Up\", \"Escape\", \"A\")");
  return key;
}

int mouse_button_of(const JsonView& v) {
  const std::string name = v.string();
  if (name == "left") return 0;
  if (name == "right") return 1;
  if (name == "middle") return 2;
  v.fail("expected \"left\", \"right\" or \"middle\"");
}

class ScriptReader {
 public:
  explicit ScriptReader(InputScript& script) : script_(script), out_(&script.steps) {}

  void read_steps(const JsonView& steps) {
    if (!steps.is_array()) steps.fail("expected an array of steps");
    count_work(steps, 1 + steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i) read_step(steps.at(i));
  }

 private:
  void read_step(const JsonView& step) {
    if (!step.is_object()) step.fail("expected a step object, e.g. {\"key\": \"Return\"}");
    std::string action;
    for (const auto& [key, value] : step.raw().items()) {
      (void)value;
      if (is_modifier(key)) continue;
      if (!action.empty()) step.fail("has two actions, \"" + action + "\" and \"" + key + "\": one per step");
      action = key;
    }
    if (action.empty()) step.fail("has no action (one of: " + action_list() + ")");
    if (action == "repeat") return read_repeat(step);
    ScriptStep s;
    s.where = step.path();
    const JsonView arg = step.at(action);
    if (action == "wait_seconds") {
      s.action = ScriptAction::wait_frames;
      s.frames = static_cast<int>(std::ceil(arg.number_in(0, 1e5) / script_.frame_seconds()));
      return add(s, step);
    }
    s.action = action_named(step, action);
    read_argument(s, step, arg);
    add(s, step);
  }

  static ScriptAction action_named(const JsonView& step, const std::string& name) {
    for (const auto& a : kActions)
      if (a.key == name) return a.action;
    step.fail("unknown action \"" + name + "\" (one of: " + action_list() + ")");
  }

  static void read_argument(ScriptStep& s, const JsonView& step, const JsonView& arg) {
    switch (s.action) {
      case ScriptAction::wait_frames:
        s.frames = frames_of(arg);
        break;
      case ScriptAction::until_screen:
        s.name = arg.string();
        s.frames = step.find("max_frames") ? frames_of(step.at("max_frames")) : 600;
        break;
      case ScriptAction::expect_screen:
      case ScriptAction::text:
      case ScriptAction::gamepad_connect:
      case ScriptAction::screenshot:
        s.name = arg.string();
        break;
      case ScriptAction::key:
      case ScriptAction::key_down:
      case ScriptAction::key_up:
        s.key = key_of(arg);
        break;
      case ScriptAction::mouse_move:
      case ScriptAction::click:
        s.points = {point_of(arg)};
        break;
      case ScriptAction::mouse_down:
      case ScriptAction::mouse_up:
        s.button = mouse_button_of(arg);
        break;
      case ScriptAction::drag:
        read_drag(s, step, arg);
        break;
      case ScriptAction::wheel:
        s.value = static_cast<float>(arg.number_in(-100, 100));
        break;
      case ScriptAction::gamepad_disconnect:
        break;
      case ScriptAction::gamepad_axis:
        read_gamepad_axis(s, step, arg);
        break;
      case ScriptAction::gamepad_button:
        read_gamepad_button(s, step, arg);
        break;
    }
    if (s.action == ScriptAction::text && s.name.empty()) arg.fail("expected some text");
    if (s.action == ScriptAction::screenshot && s.name.empty()) arg.fail("expected a PNG file name");
  }

  static void read_drag(ScriptStep& s, const JsonView& step, const JsonView& arg) {
    if (!arg.is_array() || arg.size() < 2) arg.fail("expected a path of at least 2 positions [[x, y], ...]");
    for (std::size_t i = 0; i < arg.size(); ++i) s.points.push_back(point_of(arg.at(i)));
    s.frames = int_in(step.at("frames"), 1, kMaxFrames);
  }

  static void read_gamepad_axis(ScriptStep& s, const JsonView& step, const JsonView& arg) {
    const SDL_GameControllerAxis axis = SDL_GameControllerGetAxisFromString(arg.string().c_str());
    if (axis == SDL_CONTROLLER_AXIS_INVALID)
      arg.fail("unknown axis (leftx, lefty, rightx, righty, lefttrigger, righttrigger)");
    s.axis = axis;
    s.value = static_cast<float>(step.at("value").number_in(-1, 1));
  }

  static void read_gamepad_button(ScriptStep& s, const JsonView& step, const JsonView& arg) {
    const SDL_GameControllerButton button = SDL_GameControllerGetButtonFromString(arg.string().c_str());
    if (button == SDL_CONTROLLER_BUTTON_INVALID) arg.fail("unknown button (a, b, x, y, start, back, ...)");
    s.button = button;
    s.down = step.at("down").boolean();
  }

  void read_repeat(const JsonView& step) {
    const int times = int_in(step.at("repeat"), 0, kMaxRepeat);
    if (depth_ >= kMaxRepeatDepth) step.fail("repeats nested more than " + std::to_string(kMaxRepeatDepth) + " deep");
    std::vector<ScriptStep> body;
    const std::size_t work_before = work_;
    std::vector<ScriptStep>* const outer = std::exchange(out_, &body);
    ++depth_;
    read_steps(step.at("steps"));
    --depth_;
    out_ = outer;
    if (times == 0) return;
    count_work(step, static_cast<std::size_t>(times - 1) * (work_ - work_before));
    for (int i = 0; i < times; ++i)
      for (const ScriptStep& s : body) add(s, step);
  }

  void count_work(const JsonView& where, std::size_t units) {
    work_ += units;
    if (work_ > kMaxExpansionWork)
      where.fail("the script's repeats expand to more than " + std::to_string(kMaxExpansionWork) + " passes and steps");
  }

  void add(const ScriptStep& s, const JsonView& step) {
    if (out_->size() >= kMaxExpandedSteps)
      step.fail("the script expands to more than " + std::to_string(kMaxExpandedSteps) + " steps");
    out_->push_back(s);
  }

  InputScript& script_;
  std::vector<ScriptStep>* out_;  // where read steps go: the script, or the body of the repeat being read
  int depth_ = 0;
  std::size_t work_ = 0;
};

}  // namespace

double InputScript::frame_seconds() const { return steps_per_frame * ScreenHost::kSimulationStep; }

InputScript read_input_script(const std::filesystem::path& file) {
  const Json doc = read_json_file(file);
  const JsonView root(doc, file.string());
  if (!root.is_object()) root.fail("expected an object with \"steps\"");
  InputScript script;
  script.file = file;
  if (const auto steps = root.find("steps_per_frame"))
    script.steps_per_frame = int_in(*steps, 1, kMaxScriptStepsPerFrame);
  if (const auto window = root.find("window")) {
    if (!window->is_array() || window->size() != 2) window->fail("expected [width, height] in points");
    script.width = int_in(window->at(std::size_t{0}), 320, 8192);
    script.height = int_in(window->at(std::size_t{1}), 240, 8192);
  }
  ScriptReader(script).read_steps(root.at("steps"));
  return script;
}

}  // namespace sc
