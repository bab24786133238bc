#include "app/gui/screens/learn_skill_picture.hpp"

#include <algorithm>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/core/task_kind.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/review_view/overlay_points.hpp"
#include "engine/writing/writing_trial.hpp"

namespace sc {
namespace {

TaskKind task_of(const Json& trial) { return parse_task_kind(trial.value("task", ""), "trial: $.task"); }

std::vector<ImVec2> trial_points(const Json& trial) {
  std::vector<ImVec2> points;
  if (task_of(trial) == TaskKind::parking) {
    const ParkingPath path = simulate_parking_path(parse_parking_trial(trial, "trial"));
    for (const auto& s : path.samples)
      points.emplace_back(static_cast<float>(s.vehicle.x), static_cast<float>(s.vehicle.y));
  } else {
    for (const auto& p : writing::parse_writing_trial(trial, "trial").points)
      points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  }
  return points;
}

// The points of steps [begin, end) of a trial with `steps` control steps whose path has `points` points.
std::pair<std::size_t, std::size_t> point_range(TaskKind task, int begin, int end, int steps, std::size_t points) {
  std::size_t first = 0, last = 0;
  if (task == TaskKind::parking) {
    const std::size_t per_step = static_cast<std::size_t>(parking::kSubstepsPerAction);
    first = static_cast<std::size_t>(std::max(begin, 0)) * per_step;
    last = static_cast<std::size_t>(std::max(end, 0)) * per_step;
  } else {
    // Writing steps are resampled pen steps; the segment's share of the pen path is close enough to show.
    const double T = std::max(1, steps);
    first = static_cast<std::size_t>(std::max(begin, 0) / T * static_cast<double>(points));
    last = static_cast<std::size_t>(std::max(end, 0) / T * static_cast<double>(points));
  }
  last = std::min(last, points == 0 ? 0 : points - 1);
  return {std::min(first, last), last};
}

}  // namespace

std::optional<SkillPictureData> skill_example_picture(const std::vector<ExpertDemo>& pool, int skill) {
  const auto example = example_of_skill(pool, skill);
  if (!example) return std::nullopt;
  const ExpertDemo& demo = pool[static_cast<std::size_t>(example->expert)];
  SkillPictureData out{trial_points(demo.trial)};
  std::tie(out.first, out.last) = point_range(task_of(demo.trial), example->segment.begin, example->segment.end,
                                              demo.steps.length(), out.points.size());
  return out;
}

TrialPartPictureData trial_part_picture_data(const Json& learner_trial, const Json& expert_trial, int begin, int end,
                                             int steps) {
  TrialPartPictureData out{trial_points(learner_trial), trial_points(expert_trial)};
  std::tie(out.first, out.last) = point_range(task_of(learner_trial), begin, end, steps, out.learner.size());
  return out;
}

TrialPartPictureData trial_part_picture_data(const review::SkillPlace& place) {
  return trial_part_picture_data(place.learner_trial, place.expert_trial, place.learner_begin, place.learner_end,
                                 place.learner_steps);
}

void draw_skill_picture(ImDrawList& d, ImVec2 o, ImVec2 size, const SkillPictureData& line, bool highlight) {
  d.AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(28, 33, 43, 255), 6.0f);
  if (line.points.size() < 2) return;
  ImVec2 lo = line.points[0], hi = line.points[0];
  for (const ImVec2& p : line.points) {
    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
  }
  const float pad = 8.0f;
  const float scale =
      std::min((size.x - 2 * pad) / std::max(1e-3f, hi.x - lo.x), (size.y - 2 * pad) / std::max(1e-3f, hi.y - lo.y));
  std::vector<ImVec2> mapped;
  for (const ImVec2& p : line.points)
    mapped.emplace_back(o.x + size.x * 0.5f + (p.x - (lo.x + hi.x) * 0.5f) * scale,
                        o.y + size.y * 0.5f + (p.y - (lo.y + hi.y) * 0.5f) * scale);
  review_view::draw_thick_path(d, review_view::thinned(mapped, 1.5f), IM_COL32(120, 130, 150, 90), 2.0f);
  const ImU32 color = highlight ? IM_COL32(255, 160, 90, 255) : IM_COL32(91, 155, 255, 255);
  if (line.last > line.first) {
    const std::vector<ImVec2> part(mapped.begin() + static_cast<std::ptrdiff_t>(line.first),
                                   mapped.begin() + static_cast<std::ptrdiff_t>(line.last) + 1);
    review_view::draw_thick_path(d, review_view::thinned(part, 1.5f), color, 3.5f);
  }
  d.AddCircleFilled(mapped[line.last], 4.0f, color);
}

void draw_trial_part_picture(ImDrawList& d, ImVec2 o, ImVec2 size, const TrialPartPictureData& picture,
                             const char* label) {
  review_view::draw_part_overlay(d, o, size, picture);
  // The label on a dark patch in the top left corner, at 80 % of the text size.
  const float font = ImGui::GetFontSize() * 0.8f;
  const ImVec2 text = ImGui::GetFont()->CalcTextSizeA(font, 1e9f, 0.0f, label);
  d.AddRectFilled(o, ImVec2(o.x + text.x + 8.0f, o.y + text.y + 4.0f), IM_COL32(28, 33, 43, 220), 6.0f);
  d.AddText(ImGui::GetFont(), font, ImVec2(o.x + 4.0f, o.y + 2.0f), IM_COL32(200, 208, 220, 255), label);
}

void draw_overlay_picture(ImDrawList& d, ImVec2 o, ImVec2 size, const Json& learner_trial, const Json& expert_trial) {
  const std::vector<ImVec2> learner = trial_points(learner_trial), expert = trial_points(expert_trial);
  review_view::OverlayBounds bounds;
  bounds.include(learner);
  bounds.include(expert);
  review_view::draw_overlay_points(d, o, size, learner, expert, bounds, review_view::kOverlayGuide);
}

}  // namespace sc
