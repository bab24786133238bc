#pragma once
// Glue between the review's data (teaching/review) and its painters (engine/review_view), shared by the
// Review screens and `skillcoach report`: plain conversions, no decisions.
#include <string>
#include <vector>

#include "engine/review_view/overlay_points.hpp"
#include "engine/review_view/review_chart.hpp"
#include "engine/review_view/review_images.hpp"
#include "engine/review_view/review_picture.hpp"
#include "teaching/review/before_after.hpp"
#include "teaching/review/expertise_rounds.hpp"
#include "teaching/review/trial_review.hpp"
#include "teaching/sessions/learner_hand_traces.hpp"

namespace sc {

review_view::ReviewPath review_path(const review::TrialTrack& track, const std::vector<review::SkillSpan>& spans);
// The colours of one session's pictures: the skills its diagnoses weigh (the expertise chart's) take the hues in
// turn. A session whose diagnoses cannot be read gets the default palette (by skill id).
review_view::SkillPalette session_palette(const review::ExpertiseRounds& rounds);
review_view::TrialPicture trial_picture(const review::TrialReview& trial, const review_view::SkillPalette& palette);
// Title, outcome lines, the legend of every skill in the picture (learner's, expert's and ghost's) and the plot.
review_view::TrialImageText trial_image_text(const std::string& learner, const review::TrialReview& trial);
review_view::RewardPlot reward_plot(const review::TrialReview& trial);
review_view::ExpertiseChart expertise_chart(const review::ExpertiseRounds& rounds,
                                            const review_view::SkillPalette& palette);
// The group's trials (already reviewed: `trials` indexed by seq lookup) as one overlay.
review_view::BeforeAfterPicture before_after_picture(const review::BeforeAfterGroup& group,
                                                     const std::vector<review::TrialReview>& trials);
std::vector<std::string> before_after_lines(const review::BeforeAfterGroup& group,
                                            const std::vector<review::TrialReview>& trials);
review_view::HandOverlay hand_overlay(const LearnerHandTraces& traces);
// `hand`: the reference's name ("the letters of Omniglot drawer 7").
review_view::HandImageText hand_image_text(const std::string& learner, const std::string& hand);

}  // namespace sc
