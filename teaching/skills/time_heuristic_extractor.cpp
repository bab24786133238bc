#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {

Segmentation TimeHeuristicExtractor::extract(const StepSequence& trajectory) const {
  const int t = trajectory.length();
  Segmentation out;
  // Boundaries at round(k*T/K): lengths differ by at most one, no slice is lost, order is forward.
  int begin = 0;
  for (int k = 0; k < k_; ++k) {
    int end = static_cast<int>((static_cast<long long>(t) * (k + 1) + k_ / 2) / k_);
    if (k == k_ - 1) end = t;
    if (end > begin) out.segments.push_back({k, begin, end});
    begin = end > begin ? end : begin;
  }
  return out;
}

}  // namespace sc
