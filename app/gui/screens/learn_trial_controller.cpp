#include "app/gui/screens/learn_trial_controller.hpp"

#include <imgui.h>

#include "app/gui/navigator.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "engine/core/error.hpp"

namespace sc {

const LearnTrialController::Trial& LearnTrialController::prepare() {
  TrainingSession& s = session();
  trial_ = Trial{};
  trial_.drill = s.phase() == SessionPhase::Drills || retry_item_.has_value();
  if (trial_.drill) {
    trial_.item = retry_item_ ? *retry_item_ : s.current_item();
    const PlayableDrill& drill = s.drill(trial_.item);
    trial_.reference = s.kit().drill_trial(drill);
    trial_.time_limit = s.drill_time_limit(trial_.item);
    trial_.demo_first = !retry_item_;
    if (drill.plan.target_skill >= 0)
      trial_.target = "Practises " + s.kit().describe_skill(drill.plan.target_skill) + ".";
  } else {
    trial_.reference = s.test_expert_trial();
    trial_.time_limit = s.test_time_limit();
  }
  return trial_;
}

void LearnTrialController::record_demo(const Json& demo, const TrialTimes& times) {
  try {
    note_ = session().record_demo(trial_.item, demo, times).message;
  } catch (const InputError& e) {
    note_ = e.what();
  }
}

void LearnTrialController::submit(const Json& attempt, const TrialTimes& times) {
  TrainingSession& s = session();
  result_title_ = learn_phase_title(s, false, trial_.drill);  // before the session moves on
  try {
    SubmittedTrial kept;
    if (retry_item_)
      kept = s.submit_extra_practice(*retry_item_, attempt, times);
    else if (s.phase() == SessionPhase::Drills)
      kept = s.submit_practice(attempt, times);
    else
      kept = s.submit_test_trial(attempt, times);
    last_reward_ = kept.reward;
    note_ = kept.saved.message;
    last_item_ = trial_.item;
    was_practice_ = trial_.drill;
  } catch (const InputError& e) {
    note_ = e.what();
  }
  retry_item_.reset();
}

LearnTrialController::Choice LearnTrialController::draw_result_buttons(UiContext& ui, bool confirm) {
  TrainingSession& s = session();
  const SessionPhase phase = s.phase();
  const bool testing =
      phase == SessionPhase::Drills || phase == SessionPhase::Pretest || phase == SessionPhase::Evaluation;
  Choice choice = Choice::none;
  if (was_practice_ && ImGui::Button("One more on this skill", ImVec2(-1, 40 * ui.ui_scale))) {
    retry_item_ = last_item_;
    choice = Choice::another_trial;
  } else if (learn_ui::primary_button(ui, testing ? "Next" : "Continue") || confirm) {
    choice = next(ui);
  }
  if (choice == Choice::none && was_practice_ && s.phase() == SessionPhase::Drills &&
      ImGui::Button("End practice: go to the final test", ImVec2(-1, 40 * ui.ui_scale))) {
    s.skip_practice();
    choice = next(ui);
  }
  return choice;
}

LearnTrialController::Choice LearnTrialController::next(UiContext& ui) {
  const SessionPhase phase = session().phase();
  if (phase == SessionPhase::Pretest || phase == SessionPhase::Drills || phase == SessionPhase::Evaluation)
    return Choice::another_trial;
  ui.navigator.go_to(screen_for_phase(phase));
  return Choice::other_screen;
}

}  // namespace sc
