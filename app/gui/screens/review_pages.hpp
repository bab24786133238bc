#pragma once
// The pages of the Review screen (review_screen.cpp), drawn with ImGui and the review painters.
#include <cstddef>

#include "app/gui/screen.hpp"
#include "app/gui/screens/review_model.hpp"

namespace sc {

enum class ReviewPage { Sessions, Trial, BeforeAfter, Expertise };

// Height of the top bar at UI scale 1; pages start below it.
inline constexpr float kReviewTopBar = 58.0f;

void draw_review_top_bar(UiContext& ui, ReviewModel& model, ReviewPage& page);
void draw_review_sessions(UiContext& ui, ReviewModel& model, ReviewPage& page);
void draw_review_trial(UiContext& ui, ReviewModel& model);
void draw_review_before_after(UiContext& ui, ReviewModel& model, std::size_t& group);
void draw_review_expertise(UiContext& ui, ReviewModel& model);

// A fixed, undecorated window at (x, y) of size (w, h) in framebuffer pixels.
// `scrolls`: a vertical scrollbar when the content is taller than the panel (lists that grow with the session).
void begin_review_panel(const char* id, float x, float y, float w, float h, bool scrolls = false);

}  // namespace sc
