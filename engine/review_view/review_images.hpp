#pragma once
// The review pictures as offscreen images (what `skillcoach report` writes and the golden tests compare):
// the world picture on the left, titles, legend and the reward plot on the right, text in the app's fonts.
#include <string>
#include <vector>

#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"
#include "engine/review_view/overlay_points.hpp"
#include "engine/review_view/review_chart.hpp"
#include "engine/review_view/review_picture.hpp"

namespace sc::review_view {

struct LegendEntry {
  int skill = 0;
  std::string label;  // plain words
};

struct TrialImageText {
  std::string title;                // "Ada · parking · pre-test, trial 2 (round 1)"
  std::vector<std::string> lines;   // outcome, score, device ...
  std::vector<LegendEntry> legend;  // the skills that appear in the picture
  RewardPlot plot;
};

RgbaImage render_trial_image(GlContext& context, const TrialPicture& picture, const TrialImageText& text, int width,
                             int height);
RgbaImage render_before_after_image(GlContext& context, const BeforeAfterPicture& picture, const std::string& title,
                                    const std::vector<std::string>& lines, int width, int height);

struct HandImageText {
  std::string title;               // "Ada's own hand"
  std::vector<std::string> lines;  // what the pictures show and why
  std::string guide_caption;       // "The first pre-test word over the guide"
  std::string hand_caption;        // "The same word over the letters of Omniglot drawer 7"
};

// The learner's word over the guide above the same word over the hand taken, at one scale.
RgbaImage render_hand_image(GlContext& context, const HandOverlay& overlay, const HandImageText& text, int width,
                            int height);
// Where the diagnosis' charged targets went wrong (the trainer's diagnosis page draws the same), in a grid of two
// columns: each its caption over its PartOverlay. At most kMaxPlaces, the first ones.
struct PlacePicture {
  std::string caption;  // "skill 10: ... - missed in pre-test trial 3"
  PartOverlay overlay;
};
inline constexpr std::size_t kMaxPlaces = 6;
RgbaImage render_places_image(GlContext& context, const std::vector<PlacePicture>& places, const std::string& title,
                              const std::vector<std::string>& lines, int width, int height);
// Height follows the number of skills and rounds.
RgbaImage render_expertise_chart_image(GlContext& context, const ExpertiseChart& chart, const std::string& title,
                                       int width);

}  // namespace sc::review_view
