#include "teaching/tasks/execution_noise_floor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "teaching/tasks/diagnosis.hpp"

namespace sc {

double percentile_of(const std::vector<double>& ascending, double p, const char* what) {
  if (ascending.empty()) throw InputError("noise floor", std::string("no ") + what + " to take a percentile of");
  const double at = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(ascending.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, ascending.size() - 1);
  return ascending[below] + (at - static_cast<double>(below)) * (ascending[above] - ascending[below]);
}

NoiseFloor NoiseFloorCalibration::noise_floor() const {
  NoiseFloor f(floor());
  if (!skill_twice.empty()) f.repeated_twice = percentile_of(skill_twice, kNoiseFloorPercentile, "skill medians");
  if (!skill_more.empty()) f.repeated_more = percentile_of(skill_more, kNoiseFloorPercentile, "skill medians");
  return f;
}

NoiseFloorCalibration calibrate_noise_floor(const TaskKit& kit, const std::vector<std::vector<Json>>& learners) {
  NoiseFloorCalibration out;
  for (const std::vector<Json>& trials : learners) {
    std::map<int, std::vector<double>> by_skill;
    for (const DiagnosedTrial& t : diagnose_each_trial(kit, trials, ExpertiseMode::QualityAware))
      for (std::size_t k = 0; k < t.execution.size(); ++k) {
        out.scores.push_back(t.execution[k].reward);
        by_skill[t.expert.segments[k].skill].push_back(t.execution[k].reward);
      }
    for (const auto& [skill, rewards] : by_skill) {
      if (rewards.size() == 2) out.skill_twice.push_back(median_score(rewards));
      if (rewards.size() >= static_cast<std::size_t>(kRepeatedMore)) out.skill_more.push_back(median_score(rewards));
    }
    ++out.learners;
  }
  for (std::vector<double>* v : {&out.scores, &out.skill_twice, &out.skill_more}) std::sort(v->begin(), v->end());
  return out;
}

std::string noise_floor_report(const NoiseFloorCalibration& c, const std::optional<NoiseFloor>& kit_floor) {
  char line[512];
  std::snprintf(
      line, sizeof line,
      "noise-only segment scores (%zu segments of %d learners): lowest %.3f, 0.5 %% %.3f, **%g %% %.3f** (the "
      "floor this calibration gives), 5 %% %.3f, median %.3f\n",
      c.scores.size(), c.learners, c.percentile(0.0), c.percentile(0.5), kNoiseFloorPercentile, c.floor(),
      c.percentile(5.0), c.percentile(50.0));
  std::string out = line;
  for (const auto& [values, count] :
       {std::pair{&c.skill_twice, "2 segments (their mean)"}, std::pair{&c.skill_more, "3 or more (their median)"}}) {
    if (values->empty()) continue;
    std::snprintf(line, sizeof line,
                  "noise-only skills with %s in a pre-test (%zu): lowest %.3f, **%g %% %.3f**, 5 %% %.3f, median "
                  "%.3f\n",
                  count, values->size(), values->front(), kNoiseFloorPercentile,
                  percentile_of(*values, kNoiseFloorPercentile, "skill medians"),
                  percentile_of(*values, 5.0, "skill medians"), percentile_of(*values, 50.0, "skill medians"));
    out += line;
  }
  if (!kit_floor) return out + "the kit uses no noise floor (the outlier cut alone)\n";
  std::snprintf(line, sizeof line, "the kit's noise floor: %.3f", kit_floor->segment);
  out += line;
  for (const auto& [value, label] :
       {std::pair{kit_floor->repeated_twice, "repeated twice"}, std::pair{kit_floor->repeated_more, "3 or more"}}) {
    if (!value) continue;
    std::snprintf(line, sizeof line, ", %s %.3f", label, *value);
    out += line;
  }
  return out + "\n";
}

}  // namespace sc
