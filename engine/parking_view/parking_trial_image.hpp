#pragma once
// A parking trial as a picture (what `skillcoach render --task parking` writes): the lot of its scenario, the
// path re-simulated from its actions as a trail, the car at its final state, optionally the expert's plan for
// the same scenario as a ghost ribbon, and a caption with the outcome and the legend.
#include <string>

#include "engine/parking/parking_trial.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc {

struct ParkingTrialImageOptions {
  int width = 1280;
  int height = 720;
  const ParkingPath* expert = nullptr;  // the expert's path for the same scenario, drawn as a ghost ribbon
  bool caption = true;                  // outcome and legend text (ImGui, fonts from assets/fonts)
};

// "parked at step 14 (2.8 s), return -4.12" or "not parked after 100 steps, return -38.20, collision".
std::string describe_parking_outcome(const ParkingPath& path);

// Renders into `context` (resized to the requested size) and returns the image.
RgbaImage render_parking_trial_image(GlContext& context, const ParkingTrial& trial,
                                     const ParkingTrialImageOptions& options);

}  // namespace sc
