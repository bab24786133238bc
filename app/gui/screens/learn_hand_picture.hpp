#pragma once
// The learner's own hand, pictured on the diagnosis screen. Quality-aware expertise may take one of the kit's
// references as the learner's hand (ExpertiseEstimate::learner_hand, teaching/expertise/execution_reference.hpp);
// its name ("the letters of Omniglot drawer 4") tells a learner little. Their first pre-test trial drawn over
// the guide and over that hand, at one scale, shows at a glance why their letters were measured against both.
#include <imgui.h>

#include <optional>
#include <vector>

#include "teaching/sessions/training_session.hpp"

namespace sc {

struct HandPicture {
  std::vector<ImVec2> learner, guide, hand;  // the task's trace points (x, y) of one pre-test trial
};

// nullopt when the session's diagnosis took no hand, there is no pre-test trial, or the first pre-test
// scenario's references hold none of the hand's name.
std::optional<HandPicture> learner_hand_picture(const TrainingSession& session);

// Two boxes of `box` each, `gap` apart: the learner's path over the guide, then over the hand (one scale).
void draw_hand_picture(ImDrawList& draw_list, ImVec2 top_left, ImVec2 box, float gap, const HandPicture& picture);

}  // namespace sc
