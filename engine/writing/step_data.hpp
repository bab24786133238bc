#pragma once
// Writing trajectories as per-step data for skill extraction (teaching/ turns this into sc::StepSequence;
// the engine does not depend on teaching/). Layout follows the reference's get_data_sequence (§2.5):
// state t = [x, y, timer, goal_0 .. goal_9] (13 floats) BEFORE action t; action t = (dx, dy) for the
// classic alphabet (the paper's 2-D actions) or (dx, dy, pen) for the balinese alphabet, pen 1 = drawing,
// 0 = moving lifted. N states and N actions (no final state), as in the reference.
#include <string_view>
#include <vector>

#include "engine/writing/word_trajectory.hpp"

namespace sc::writing {

inline constexpr int kWritingStateDim = 3 + kMaxWordSymbols;

struct WritingStepData {
  int state_dim = kWritingStateDim;
  int action_dim = 2;
  std::vector<float> states;          // T x state_dim, row-major
  std::vector<float> actions;         // T x action_dim, row-major
  std::vector<int> character_starts;  // action index where each symbol begins (expert words only)
  int length() const { return action_dim > 0 ? static_cast<int>(actions.size()) / action_dim : 0; }
};

int writing_action_dim(AlphabetKind kind);

// The expert's word with its true character boundaries.
WritingStepData expert_step_data(const WordTrajectory& word);

// A learner's trace (already infilled, see infill_trace) for the goal `word`: actions are consecutive
// differences; character boundaries are unknown, so character_starts stays empty.
WritingStepData trace_step_data(const std::vector<TracePoint>& points, AlphabetKind kind, std::string_view word);

}  // namespace sc::writing
