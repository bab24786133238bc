#pragma once
// What every trial screen of the trainer does with the session around one trial, whatever the task: which
// trial comes next (the current test item, the current drill, or the drill the learner asked one more of),
// recording the demo, submitting the attempt to the right TrainingSession call, and the result card's
// choices ("One more on this skill", "Next", "End practice"). The parking and writing trial screens are
// views over it: they play the trial and draw it.
#include <optional>
#include <string>

#include "app/gui/screen.hpp"
#include "app/gui/screens/learn_flow.hpp"

namespace sc {

class LearnTrialController {
 public:
  // The trial about to be played.
  struct Trial {
    bool drill = false;       // a drill (demo + practice, or a retry without demo); else a test trial
    int item = 0;             // the curriculum item of a drill
    Json reference;           // the drill's trial (kit.drill_trial) or the test's expert trial
    double time_limit = 0.0;  // seconds
    bool demo_first = false;  // a drill's first play starts with the expert's demo
    std::string target;       // "Practises <skill words>." for an individualized drill, else empty
  };

  explicit LearnTrialController(LearnFlow& flow) : flow_(flow) {}

  TrainingSession& session() { return *flow_.session(); }
  // Sets up and returns the next trial: the retry asked for, else the session's current item.
  const Trial& prepare();
  const Trial& trial() const { return trial_; }

  // A finished demo (the expert's trial as played); the note says if it is pending.
  void record_demo(const Json& demo, const TrialTimes& times);
  // The learner's attempt, to submit_extra_practice, submit_practice or submit_test_trial.
  void submit(const Json& attempt, const TrialTimes& times);

  // After submit: what the result card shows.
  double last_reward() const { return last_reward_; }
  const std::string& note() const { return note_; }
  const std::string& result_title() const { return result_title_; }  // the header of the trial just ended
  bool was_practice() const { return was_practice_; }

  enum class Choice { none, another_trial, other_screen };
  // The result card's buttons under the task's own lines; `confirm` (Enter, A) presses "Next". On
  // another_trial the caller prepares and plays it; on other_screen the navigator has moved on.
  Choice draw_result_buttons(UiContext& ui, bool confirm);

 private:
  Choice next(UiContext& ui);

  LearnFlow& flow_;
  Trial trial_;
  std::optional<int> retry_item_;
  int last_item_ = 0;
  bool was_practice_ = false;
  double last_reward_ = 0.0;
  std::string note_;
  std::string result_title_;
};

}  // namespace sc
