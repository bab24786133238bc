#pragma once
// Offscreen images of the writing canvas (OSMesa or EGL, chosen by SKILLCOACH_GL, see gl_context.hpp):
// deterministic for a given GL driver, used by `skillcoach render --task writing` and the golden tests.
#include <filesystem>

#include "engine/render/rgba_image.hpp"
#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/writing_scene.hpp"

namespace sc::writing_view {

struct WritingRenderOptions {
  bool overlay_expert = false;  // the gold word as a ghost ribbon (start dot, direction arrows) under the ink
  bool show_guide = true;       // the goal word faint underneath, as the learner saw it
  bool show_score = true;       // the score badge (computed from the trace; skipped for an empty trace)
  int width = 1000;             // pixels; the 500 x 300 canvas is fitted with its aspect kept
  int height = 600;
  std::filesystem::path data_dir;  // Omniglot stroke data for the gold word; empty: writing::omniglot_data_dir()
};

// Draws `scene` on a fresh offscreen context of width x height pixels.
RgbaImage render_writing_scene_image(const WritingScene& scene, int width, int height);

// The scene of a trial file: guide and ribbon from the trial's scenario, the trial's points as ink, the score
// and a caption ("ab-c · classic · learner, mouse").
WritingScene writing_trial_scene(const writing::WritingTrial& trial, const WritingRenderOptions& options);
RgbaImage render_writing_trial_image(const writing::WritingTrial& trial, const WritingRenderOptions& options);
// Writes the image as a PNG (parent folders created). Throws InputError for missing stroke data, a failing
// GL context or an unwritable file.
void render_writing_trial_png(const writing::WritingTrial& trial, const WritingRenderOptions& options,
                              const std::filesystem::path& out);

}  // namespace sc::writing_view
