#pragma once
// Calibrating quality-aware expertise's noise floor (execution_expertise.hpp): what realistic noise alone
// does to a task's execution score. A learner who writes or drives everything as the expert does, only with
// a realistic hand and device, still scores below 0 on many segments; the floor is the score that such
// noise reaches on only kNoiseFloorPercentile % of segments, so a segment scoring worse is evidence of a
// deficit and one scoring better is not.
//
// Spec. Every learner's trials are segmented and aligned as the app diagnoses them (diagnose_each_trial,
// quality-aware); the scores are the raw execution scores of all expert segments of all trials
// (DiagnosedTrial::execution). The repeated floors take, per learner, each skill's median_score over its
// segments in the learner's pre-test, for skills with exactly 2 segments and with kRepeatedMore or more
// (execution_expertise.hpp, repeated evidence). Percentiles interpolate linearly between order statistics. The
// shipped kits' floors are calibrated on the planted tables' noise-only learners at seed 0, which no table is
// reported at (docs/skills.md).
#include <optional>
#include <string>
#include <vector>

#include "teaching/sessions/task_kit.hpp"

namespace sc {

// Chosen before the first calibration and not varied: one segment in a hundred.
inline constexpr double kNoiseFloorPercentile = 1.0;

// The p-th percentile (p in [0, 100]) of ascending values; InputError naming `what` when there are none.
double percentile_of(const std::vector<double>& ascending, double p, const char* what);

struct NoiseFloorCalibration {
  int learners = 0;
  std::vector<double> scores;       // every segment's raw execution score, ascending
  std::vector<double> skill_twice;  // each learner's skills with 2 segments: their mean score, ascending
  std::vector<double> skill_more;   // ... with kRepeatedMore or more: their median score, ascending
  double percentile(double p) const { return percentile_of(scores, p, "segment scores"); }
  double floor() const { return percentile(kNoiseFloorPercentile); }
  // All three at kNoiseFloorPercentile; a repeated floor without any skill of its count is absent.
  NoiseFloor noise_floor() const;
};

// `learners`: each learner's pre-test trials (documents of the kit's task).
NoiseFloorCalibration calibrate_noise_floor(const TaskKit& kit, const std::vector<std::vector<Json>>& learners);

// "noise-only segment scores (N segments of L learners): 1 % -0.50, 5 % ..., median ...", the repeated
// floors' lines, then the kit's floor
std::string noise_floor_report(const NoiseFloorCalibration& calibration, const std::optional<NoiseFloor>& kit_floor);

}  // namespace sc
