#pragma once
// The progress line of the long experiment commands (simulate-students, both tasks).
#include "teaching/students/student_experiment.hpp"

namespace sc::cli {

// One updating line on a terminal; otherwise one line per finished phase (logs stay short).
ExperimentProgress progress_printer();

}  // namespace sc::cli
