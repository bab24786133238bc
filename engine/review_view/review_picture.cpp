#include "engine/review_view/review_picture.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/car_painter.hpp"
#include "engine/parking_view/lot_painter.hpp"
#include "engine/review_view/review_palette.hpp"
#include "engine/writing_view/canvas_geometry.hpp"
#include "engine/writing_view/canvas_painter.hpp"

namespace sc::review_view {
namespace {

constexpr float kMinParkingWidth = 24.0f;  // metres: keeps a short drill from filling the picture
constexpr float kParkingMargin = 4.0f;

PathStyle round_style() {
  PathStyle style;
  style.join = LineJoin::round;
  style.cap = LineCap::round;
  return style;
}

void include(WorldRect& box, Vec2f p) {
  box.min_x = std::min(box.min_x, p.x);
  box.min_y = std::min(box.min_y, p.y);
  box.max_x = std::max(box.max_x, p.x);
  box.max_y = std::max(box.max_y, p.y);
}

ParkingScenario parking_scenario(const Json& scenario) {
  return parse_parking_scenario(JsonView(scenario, "review scenario"));
}

Camera2D fit(WorldRect box, PixelViewport viewport) {
  box.min_x -= kParkingMargin;
  box.max_x += kParkingMargin;
  box.min_y -= kParkingMargin;
  box.max_y += kParkingMargin;
  const float cx = (box.min_x + box.max_x) / 2, cy = (box.min_y + box.max_y) / 2;
  // Widen the box to the viewport's aspect so the camera keeps the scale the same in x and y.
  float w = std::max(box.max_x - box.min_x, kMinParkingWidth), h = box.max_y - box.min_y;
  const float aspect = viewport.width / viewport.height;
  if (w / h < aspect)
    w = h * aspect;
  else
    h = w / aspect;
  return Camera2D({cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2}, viewport, WorldYAxis::down);
}

Camera2D parking_camera(const std::vector<Json>& scenarios, const std::vector<std::span<const Vec2f>>& paths,
                        PixelViewport viewport) {
  WorldRect box{1e9f, 1e9f, -1e9f, -1e9f};
  for (const Json& s : scenarios) {
    const Pose goal = goal_pose(parking_scenario(s));
    include(box, {static_cast<float>(goal.x), static_cast<float>(goal.y)});
  }
  for (const auto& path : paths)
    for (Vec2f p : path) include(box, p);
  if (box.min_x > box.max_x) box = {-10, -10, 10, 10};
  return fit(box, viewport);
}

// What sets the tasks' pictures apart, in one place (widths in world units: metres, canvas pixels).
struct TaskLook {
  bool paper = false;          // writing paper under everything; else the parking lot and its goals
  float expert_ribbon = 2.0f;  // the car's width / a wide pen band
  float before_after_ribbon = 2.0f;
  float ghost_lane = 2.0f;    // a faint lane under the drill's dashes
  Color ghost = kGhostDrill;  // white dashes read on the grey lot, dark ones on the paper
  bool car_marker = true;     // the playhead is the car (with headings); else a round pen tip
};

TaskLook look_of(TaskKind task) {
  if (task == TaskKind::parking) return {};
  return {true, 14.0f, 12.0f, 10.0f, Color::hex(0x3b4a6b, 0.9f), false};
}

void paint_background(Renderer2D& renderer, TaskKind task, const std::vector<Json>& scenarios) {
  if (look_of(task).paper) {
    writing_view::paint_paper(renderer);
    return;
  }
  if (scenarios.empty()) return;
  const ParkingScenario first = parking_scenario(scenarios.front());
  paint_lot(renderer, make_layout(first));
  for (const Json& s : scenarios) {
    const ParkingScenario scenario = parking_scenario(s);
    paint_goal(renderer, goal_pose(scenario), scenario.reverse_in);
  }
}

std::span<const Vec2f> span_points(const ReviewPath& path, const PathSpan& span) {
  const int n = static_cast<int>(path.points.size());
  const int begin = std::clamp(span.begin, 0, n - 1);
  const int end = std::clamp(span.end, begin, n - 1);
  return std::span<const Vec2f>(path.points)
      .subspan(static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin + 1));
}

// The path in skill colours over a dark casing, with a bead at every boundary between two skills.
void paint_skill_path(Renderer2D& renderer, const ReviewPath& path, const SkillPalette& palette, float width,
                      float alpha) {
  if (path.points.size() < 2) return;
  const PathStyle style = round_style();
  renderer.polyline(path.points, Stroke::pixels(width + 3.0f), Color::hex(0x101418, 0.7f * alpha), style);
  if (path.spans.empty()) {
    renderer.polyline(path.points, Stroke::pixels(width), Color::hex(0xffe28a, alpha), style);
    return;
  }
  for (const PathSpan& span : path.spans)
    renderer.polyline(span_points(path, span), Stroke::pixels(width), palette.color(span.skill, alpha), style);
  const float bead = width * 1.3f / renderer.camera().pixels_per_unit();
  for (std::size_t i = 1; i < path.spans.size(); ++i) {
    const int at = std::clamp(path.spans[i].begin, 0, static_cast<int>(path.points.size()) - 1);
    const Vec2f p = path.points[static_cast<std::size_t>(at)];
    renderer.fill_circle(p, bead, Color::hex(0xffffff, alpha));
    renderer.outline_circle(p, bead, Stroke::pixels(2.0f), Color::hex(0x101418, alpha));
  }
}

void paint_expert(Renderer2D& renderer, TaskKind task, const ReviewPath& expert, const SkillPalette& palette) {
  if (expert.points.size() < 2) return;
  renderer.ghost_ribbon(expert.points, Stroke::world(look_of(task).expert_ribbon), kExpertRibbon, round_style());
  paint_skill_path(renderer, expert, palette, 2.0f, 0.75f);
}

void paint_ghost(Renderer2D& renderer, TaskKind task, const ReviewPath& ghost) {
  if (ghost.points.size() < 2) return;
  const float unit = 1.0f / renderer.camera().pixels_per_unit();
  const TaskLook look = look_of(task);
  // The faint lane keeps the drill visible where the learner's line covers it.
  renderer.ghost_ribbon(ghost.points, Stroke::world(look.ghost_lane), look.ghost.with_alpha(0.16f), round_style());
  const Color color = look.ghost;
  renderer.dashed_polyline(ghost.points, Stroke::pixels(3.0f), {14.0f * unit, 9.0f * unit}, color, round_style());
}

void paint_marker(Renderer2D& renderer, TaskKind task, const ReviewPath& path, double position) {
  if (path.points.empty()) return;
  const Vec2f p = position_at(path, position);
  if (look_of(task).car_marker && !path.headings.empty()) {
    paint_car(renderer, CarPose{p, heading_at(path, position), 0.0f}, reference_car_look());
  } else {
    const float r = 5.0f / renderer.camera().pixels_per_unit() * 1.6f;
    renderer.fill_circle(p, r, Color::hex(0x1d2330));
    renderer.outline_circle(p, r, Stroke::pixels(2.0f), Color::hex(0xffffff));
  }
}

}  // namespace

Vec2f position_at(const ReviewPath& path, double position) {
  if (path.points.empty()) return {};
  const double last = static_cast<double>(path.points.size() - 1);
  const double t = std::clamp(position, 0.0, last);
  const std::size_t i = static_cast<std::size_t>(std::floor(t));
  if (i + 1 >= path.points.size()) return path.points.back();
  const float a = static_cast<float>(t - static_cast<double>(i));
  const Vec2f p = path.points[i], q = path.points[i + 1];
  return {p.x + (q.x - p.x) * a, p.y + (q.y - p.y) * a};
}

float heading_at(const ReviewPath& path, double position) {
  if (path.headings.empty()) return 0.0f;
  const double last = static_cast<double>(path.headings.size() - 1);
  const double t = std::clamp(position, 0.0, last);
  const std::size_t i = static_cast<std::size_t>(std::floor(t));
  if (i + 1 >= path.headings.size()) return path.headings.back();
  // Along the shorter arc, so a heading crossing ±π does not spin the car.
  const float a = static_cast<float>(t - static_cast<double>(i));
  const float h0 = path.headings[i];
  const float d = std::remainder(path.headings[i + 1] - h0, 2.0f * static_cast<float>(M_PI));
  return h0 + d * a;
}

Camera2D trial_picture_camera(const TrialPicture& picture, PixelViewport viewport) {
  if (look_of(picture.task).paper) return writing_view::writing_canvas_camera(viewport);
  std::vector<std::span<const Vec2f>> paths{picture.learner.points};
  if (picture.expert) paths.emplace_back(picture.expert->points);
  if (picture.ghost) paths.emplace_back(picture.ghost->points);
  return parking_camera({picture.scenario}, paths, viewport);
}

Camera2D before_after_camera(const BeforeAfterPicture& picture, PixelViewport viewport) {
  if (look_of(picture.task).paper) return writing_view::writing_canvas_camera(viewport);
  std::vector<std::span<const Vec2f>> paths;
  for (const auto* group : {&picture.before, &picture.after, &picture.experts})
    for (const auto& p : *group) paths.emplace_back(p);
  return parking_camera(picture.scenarios, paths, viewport);
}

void paint_trial_picture(Renderer2D& renderer, const TrialPicture& picture) {
  paint_background(renderer, picture.task, {picture.scenario});
  if (picture.expert) paint_expert(renderer, picture.task, *picture.expert, picture.palette);
  if (picture.ghost) paint_ghost(renderer, picture.task, *picture.ghost);
  paint_skill_path(renderer, picture.learner, picture.palette, 5.0f, 1.0f);
  paint_marker(renderer, picture.task, picture.learner,
               picture.playhead.value_or(static_cast<double>(picture.learner.points.size()) - 1.0));
}

void paint_before_after(Renderer2D& renderer, const BeforeAfterPicture& picture) {
  paint_background(renderer, picture.task, picture.scenarios);
  const PathStyle style = round_style();
  const float ribbon = look_of(picture.task).before_after_ribbon;
  for (const auto& p : picture.experts) renderer.ghost_ribbon(p, Stroke::world(ribbon), kExpertRibbon, style);
  for (const auto& p : picture.before) {
    renderer.polyline(p, Stroke::pixels(6.0f), Color::hex(0x101418, 0.6f), style);
    renderer.polyline(p, Stroke::pixels(3.5f), kBefore, style);
  }
  for (const auto& p : picture.after) {
    renderer.polyline(p, Stroke::pixels(6.0f), Color::hex(0x101418, 0.6f), style);
    renderer.polyline(p, Stroke::pixels(3.5f), kAfter, style);
  }
}

}  // namespace sc::review_view
