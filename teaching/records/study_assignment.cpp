#include "teaching/records/study_assignment.hpp"

#include <algorithm>

#include "engine/core/rng.hpp"

namespace sc::records {

std::vector<std::string> assignment_sequence(const StudyDefinition& study) {
  Rng rng = Rng(study.seed).fork(0x5374756479ULL);  // "Study": a stream of its own
  std::vector<std::string> sequence;
  sequence.reserve(static_cast<std::size_t>(std::max(study.capacity(), 0)));
  int remaining = study.target_per_condition;  // per condition: every block takes the same from each
  while (remaining > 0) {
    // Each condition once or twice; twice only while at least two places per condition remain.
    const int repeats = remaining >= 2 && rng.below(2) == 1 ? 2 : 1;
    std::vector<std::string> block;
    for (int r = 0; r < repeats; ++r) block.insert(block.end(), study.conditions.begin(), study.conditions.end());
    for (std::size_t i = block.size(); i > 1; --i) std::swap(block[i - 1], block[rng.below(i)]);  // Fisher-Yates
    sequence.insert(sequence.end(), block.begin(), block.end());
    remaining -= repeats;
  }
  return sequence;
}

}  // namespace sc::records
