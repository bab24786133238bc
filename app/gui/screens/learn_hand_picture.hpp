#pragma once
// The learner's own hand, pictured (the trainer's diagnosis page and the review's "diagnosis explained"): a
// reference's name ("the letters of Omniglot drawer 4") tells a learner little; their pre-test word drawn over
// the guide and over that hand, at one scale, shows at a glance why their letters were measured against both
// (teaching/sessions/learner_hand_traces.hpp).
#include <optional>
#include <string>

#include "teaching/sessions/learner_hand_traces.hpp"
#include "teaching/sessions/training_session.hpp"

namespace sc {

// The session's first pre-test trial, guide and hand; nullopt when the diagnosis took no hand.
std::optional<LearnerHandTraces> learner_hand_picture(const TrainingSession& session);

// Captions above both boxes ("<whose> word over the guide", "... over <hand>"), the boxes filling the window's
// width, then the cursor below them.
void hand_picture_row(const LearnerHandTraces& traces, const std::string& whose, const std::string& hand,
                      float box_height, float gap);

}  // namespace sc
