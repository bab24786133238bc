// The instructor's Review mode: a sortable browser of learners' sessions, a trial viewer (the learner's path
// over the expert's, segments coloured by skill with each skill's small picture, the drill's ghost, playback
// with the car or pen moving and the input stick, reward over time), the before/after overlays and the
// expertise chart with the diagnosis explained. One screen with four pages (the selection survives page
// changes); "review_trial", "review_before_after" and "review_expertise" open it on that page.
// The data comes from teaching/review, the pictures from engine/review_view (see review_model.hpp).
#include <imgui.h>

#include <memory>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/review_model.hpp"
#include "app/gui/screens/review_pages.hpp"

namespace sc {
namespace {

class ReviewScreen final : public Screen {
 public:
  ReviewScreen(AppServices& services, ReviewPage page) : model_(services), page_(page) {}

  void update(const FrameInput& input, double dt) override {
    if (page_ == ReviewPage::Trial) {
      if (input.keys_pressed[SDL_SCANCODE_SPACE] && !input.ui_wants_keyboard) model_.playback().toggle();
      model_.playback().advance(dt);
    }
  }

  void draw(UiContext& ui) override {
    draw_review_top_bar(ui, model_, page_);
    switch (page_) {
      case ReviewPage::Sessions:
        draw_review_sessions(ui, model_, page_);
        break;
      case ReviewPage::Trial:
        draw_review_trial(ui, model_);
        break;
      case ReviewPage::BeforeAfter:
        draw_review_before_after(ui, model_, group_);
        break;
      case ReviewPage::Expertise:
        draw_review_expertise(ui, model_);
        break;
    }
  }

 private:
  ReviewModel model_;
  ReviewPage page_;
  std::size_t group_ = 0;
};

ScreenFactory open_on(ReviewPage page) {
  return [page](AppServices& services) { return std::make_unique<ReviewScreen>(services, page); };
}

const ScreenRegistration kSessions{
    {"review", "Review: learners' sessions (instructor)", open_on(ReviewPage::Sessions)}};
const ScreenRegistration kTrial{{"review_trial", "Review: trial viewer with playback", open_on(ReviewPage::Trial)}};
const ScreenRegistration kBeforeAfter{
    {"review_before_after", "Review: before/after overlays", open_on(ReviewPage::BeforeAfter)}};
const ScreenRegistration kExpertise{
    {"review_expertise", "Review: expertise across rounds, diagnosis explained", open_on(ReviewPage::Expertise)}};

}  // namespace
}  // namespace sc
