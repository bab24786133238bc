#pragma once
// Balanced randomisation of a study's participants: permuted blocks. The sequence of conditions is cut
// into blocks that hold every condition equally often (once or twice, block size chosen at random so the
// coordinator cannot foresee the last assignment of a block), each block shuffled; the whole sequence holds
// every condition exactly `target_per_condition` times. Participant i (in enrolment order) gets element i,
// so the assignment is a function of the study's seed and the enrolment order alone, a condition never
// receives more than its target, and the study is full after capacity() participants.
// The shuffles use engine/core/rng.hpp (same seed, same sequence on every platform).
#include <string>
#include <vector>

#include "teaching/records/study_records.hpp"

namespace sc::records {

// The conditions of participants 0 .. capacity()-1, in enrolment order.
std::vector<std::string> assignment_sequence(const StudyDefinition& study);

}  // namespace sc::records
