#pragma once
// Dynamic time warping between an expert's trace and a learner's, so that each expert skill segment can be
// matched with the part of the learner's trial that did the same thing, however much faster, slower or
// later the learner was (quality-aware expertise, execution_expertise.hpp).
//
// Spec: classic DTW, steps (i-1, j), (i, j-1), (i-1, j-1), local cost the Euclidean distance of the points,
// path from (0, 0) to (n-1, m-1). Ties prefer the diagonal, then the expert's step. O(n m) time; n m bytes and
// two rows of costs of memory.
#include <array>
#include <utility>
#include <vector>

namespace sc {

// A point of a trace in the task's own units (parking: x, y in m and signed speed in m/s; writing: x, y px).
using TracePoint3 = std::array<double, 3>;

// (expert step, learner step) pairs in order; empty when either trace is empty.
using StepAlignment = std::vector<std::pair<int, int>>;
StepAlignment align_traces(const std::vector<TracePoint3>& expert, const std::vector<TracePoint3>& learner);

// align_traces on every `stride`-th point of both (stride >= 1), spread back over the steps between: expert
// step i of block a goes with the step at the same place in each learner block b that a is paired with (clamped
// to the learner's last step), and the last steps with each other; sorted, no repeats. For long traces whose
// alignment only has to say which part does what: stride^2 times cheaper.
StepAlignment align_traces_strided(const std::vector<TracePoint3>& expert, const std::vector<TracePoint3>& learner,
                                   int stride);
// The same spreading for a path found on every `stride`-th step of traces of `expert_length` and
// `learner_length` steps.
StepAlignment spread_strided(const StepAlignment& coarse, int stride, int expert_length, int learner_length);

// The learner's steps aligned with expert steps [begin, end): {first, last + 1}; {0, 0} when none.
std::pair<int, int> aligned_span(const StepAlignment& path, int begin, int end);

}  // namespace sc
