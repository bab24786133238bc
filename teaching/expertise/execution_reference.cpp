#include "teaching/expertise/execution_reference.hpp"

#include <algorithm>

namespace sc {
namespace {

// The pairs of `path` (ascending in the expert's step) whose expert step is in [begin, end).
std::pair<StepAlignment::const_iterator, StepAlignment::const_iterator> pairs_in(const StepAlignment& path, int begin,
                                                                                 int end) {
  const auto by_expert = [](const std::pair<int, int>& pair, int step) { return pair.first < step; };
  const auto first = std::lower_bound(path.begin(), path.end(), begin, by_expert);
  return {first, std::lower_bound(first, path.end(), end, by_expert)};
}

}  // namespace

StepAlignment through_reference(const ExecutionReference& reference, const StepAlignment& expert_to_learner, int begin,
                                int end) {
  const auto [learner, learner_end] = pairs_in(expert_to_learner, begin, end);
  const auto [ref, ref_end] = pairs_in(reference.from_expert, begin, end);
  StepAlignment out;
  auto j = learner;
  for (auto k = ref; k != ref_end; ++k) {
    while (j != learner_end && j->first < k->first) ++j;
    for (auto same = j; same != learner_end && same->first == k->first; ++same)
      out.push_back({k->second, same->second});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace sc
