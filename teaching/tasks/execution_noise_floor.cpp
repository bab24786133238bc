#include "teaching/tasks/execution_noise_floor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/core/error.hpp"
#include "teaching/tasks/diagnosis.hpp"

namespace sc {

double NoiseFloorCalibration::percentile(double p) const {
  if (scores.empty()) throw InputError("noise floor", "no segment scores to take a percentile of");
  const double at = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(scores.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, scores.size() - 1);
  return scores[below] + (at - static_cast<double>(below)) * (scores[above] - scores[below]);
}

NoiseFloorCalibration calibrate_noise_floor(const TaskKit& kit, const std::vector<std::vector<Json>>& learners) {
  NoiseFloorCalibration out;
  for (const std::vector<Json>& trials : learners) {
    for (const DiagnosedTrial& t : diagnose_each_trial(kit, trials, ExpertiseMode::QualityAware))
      for (const SegmentExecution& s : t.execution) out.scores.push_back(s.reward);
    ++out.learners;
  }
  std::sort(out.scores.begin(), out.scores.end());
  return out;
}

std::string noise_floor_report(const NoiseFloorCalibration& c, std::optional<double> kit_floor) {
  char line[512];
  std::snprintf(
      line, sizeof line,
      "noise-only segment scores (%zu segments of %d learners): lowest %.3f, 0.5 %% %.3f, **%g %% %.3f** (the "
      "floor this calibration gives), 5 %% %.3f, median %.3f\n",
      c.scores.size(), c.learners, c.percentile(0.0), c.percentile(0.5), kNoiseFloorPercentile, c.floor(),
      c.percentile(5.0), c.percentile(50.0));
  std::string out = line;
  if (kit_floor)
    std::snprintf(line, sizeof line, "the kit's noise floor: %.3f\n", *kit_floor);
  else
    std::snprintf(line, sizeof line, "the kit uses no noise floor (the outlier cut alone)\n");
  return out + line;
}

}  // namespace sc
