#pragma once
// The review's world pictures, drawn with Renderer2D in the task's world units (parking: metres on the
// lot; writing: canvas pixels): a trial over the expert's path with the learner's segments coloured by
// skill and boundaries marked, the drill's ghost path dashed, and the car or pen at a playback time; and
// the before/after overlay of many trials. Text (titles, legends) is left to the caller (ImGui).
#include <optional>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/core/task_kind.hpp"
#include "engine/render/camera2d.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/review_view/review_palette.hpp"

namespace sc::review_view {

struct PathSpan {
  int skill = 0;
  int begin = 0;  // step index: the span is the polyline points[begin..end]
  int end = 0;
};

struct ReviewPath {
  std::vector<Vec2f> points;    // T + 1 positions (before each step, then the end)
  std::vector<float> headings;  // parking: per point (radians); empty for writing
  std::vector<PathSpan> spans;  // skill segments; empty: drawn in one colour
};

struct TrialPicture {
  TaskKind task = TaskKind::parking;
  Json scenario;  // the learner's scenario (lot and goal, or the word's canvas)
  ReviewPath learner;
  std::optional<ReviewPath> expert;  // wide translucent ribbon under everything, thin skill-coloured core
  std::optional<ReviewPath> ghost;   // the drill the learner practised: dashed white
  std::optional<double> playhead;    // step position (fractional) of the car/pen to draw; none: the end
  SkillPalette palette;              // the session's skill colours (the legend's too)
};

struct BeforeAfterPicture {
  TaskKind task = TaskKind::parking;
  std::vector<Json> scenarios;              // every goal drawn (parking); the first sets the canvas (writing)
  std::vector<std::vector<Vec2f>> before;   // pre-test paths
  std::vector<std::vector<Vec2f>> after;    // evaluation paths
  std::vector<std::vector<Vec2f>> experts;  // the experts' paths of the same scenarios, faint
};

// A camera that shows everything the picture holds (parking: every path and goal with a margin, at least
// 24 m wide; writing: the whole canvas), fitted into `viewport` with its aspect kept.
Camera2D trial_picture_camera(const TrialPicture& picture, PixelViewport viewport);
Camera2D before_after_camera(const BeforeAfterPicture& picture, PixelViewport viewport);

// Both draw after renderer.set_camera(...) with the camera above.
void paint_trial_picture(Renderer2D& renderer, const TrialPicture& picture);
void paint_before_after(Renderer2D& renderer, const BeforeAfterPicture& picture);

// Where the car or pen is at fractional step `position` of a path (clamped), and its heading (parking).
Vec2f position_at(const ReviewPath& path, double position);
float heading_at(const ReviewPath& path, double position);

}  // namespace sc::review_view
