#pragma once
// The writing students' pen: a BcPolicy (tanh-bounded MLP) on the reference's 13-float writing state
// (reference-facts §2.5: [x, y, timer, goal_0..9]) -> pen step (dx, dy), classic alphabet.
// The network sees the state scaled to about [-1, 1] (raw x runs to 500 px and the timer to ~2700 steps,
// which an MLP trained with a 5e-4 learning rate barely resolves) and predicts the step divided by
// kPenActionScale: the connector '^' steps dy = ±2, outside tanh's range.
// A rollout is what the expert's step data is, built from the pen's own path: the pen starts at the word's
// start (0, 150); state t = [its own position, t, the word's goal]; it moves for the expert's number of steps.
#include <vector>

#include "engine/writing/trace_point.hpp"
#include "engine/writing/word_trajectory.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

inline constexpr double kPenActionScale = 2.0;

// One raw 13-float state in the network's units.
std::vector<float> pen_features(const float* raw_state);
// Raw (13-D state, 2-D step) pairs -> network units. InputError unless the dimensions are 13 and 2.
BcDataset pen_dataset(const BcDataset& raw);

// The pen's trace: the start plus one point per step (gold.steps.size() steps), kept on the canvas.
std::vector<writing::TracePoint> rollout_pen(const BcPolicy& policy, const writing::WordTrajectory& gold);

// min(score_writing(gold, trace).score, 0): the kit's reward_of for a classic word, in [-1, 0].
double pen_trace_reward(const writing::WordTrajectory& gold, const std::vector<writing::TracePoint>& trace);

// Mean pen_trace_reward of the policy's rollouts of the words.
double score_pen_student(const BcPolicy& policy, const std::vector<writing::WordTrajectory>& words);

}  // namespace sc
