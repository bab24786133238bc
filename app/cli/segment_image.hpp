#pragma once
// The picture `skillcoach segment --png` writes (the paper's appendix figure): a trial's path with each
// skill segment in its skill's colour, boundaries as dots, and a legend naming each segment's skill and steps.
#include <string>
#include <vector>

#include "app/core/skill_colors.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/render/draw_types.hpp"
#include "engine/render/rgba_image.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc::cli {

// `segmentation` is in the trial's control steps (parking_step_sequence): step t is drawn from the path's
// sample 3t to 3t+3 (three simulation sub-steps per control step).
RgbaImage render_parking_segments(const ParkingTrial& trial, const Segmentation& segmentation,
                                  const std::string& caption, int width, int height);
// `points` are the infilled trace the steps were made from (step t runs from points[t] to points[t+1]).
RgbaImage render_writing_segments(const writing::WritingTrial& trial, const std::vector<writing::TracePoint>& points,
                                  const Segmentation& segmentation, const std::string& caption, int width, int height);

}  // namespace sc::cli
