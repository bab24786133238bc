#include "teaching/expertise/expertise_estimation.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "engine/core/error.hpp"

namespace sc {
namespace {

std::string trial_name(std::size_t index, int scenario) {
  return "expertise trial " + std::to_string(index) + " (scenario " + std::to_string(scenario) + ")";
}

void check_skills(const Segmentation& seg, int num_skills, std::size_t index, int scenario, const char* whose) {
  for (const auto& s : seg.segments) {
    if (s.skill < 0 || s.skill >= num_skills) {
      throw InputError(trial_name(index, scenario), std::string(whose) + " skill id " + std::to_string(s.skill) +
                                                        " is outside [0, " + std::to_string(num_skills) + ")");
    }
  }
}

}  // namespace

bool ExpertiseEstimate::penalised(int skill) const {
  if (skill < 0 || skill >= num_skills()) return false;
  return expertise[static_cast<std::size_t>(skill)] < 0.0;
}

void rank_expertise(ExpertiseEstimate& estimate, int num_targets) {
  if (num_targets < 0) throw InputError("expertise estimation", "the number of target skills must be >= 0");
  estimate.ranking.clear();
  for (int m = 0; m < estimate.num_skills(); ++m) {
    if (estimate.occurrences[static_cast<std::size_t>(m)] > 0) estimate.ranking.push_back(m);
  }
  const auto& e = estimate.expertise;
  const auto& occ = estimate.occurrences;
  std::sort(estimate.ranking.begin(), estimate.ranking.end(), [&](int a, int b) {
    const auto ia = static_cast<std::size_t>(a);
    const auto ib = static_cast<std::size_t>(b);
    if (e[ia] != e[ib]) return e[ia] < e[ib];
    if (occ[ia] != occ[ib]) return occ[ia] > occ[ib];
    return a < b;
  });
  const std::size_t n = std::min(estimate.ranking.size(), static_cast<std::size_t>(num_targets));
  estimate.targets.assign(estimate.ranking.begin(), estimate.ranking.begin() + static_cast<long>(n));
}

ExpertiseEstimate estimate_expertise(const std::vector<ExpertiseTrial>& trials, int num_skills, int num_targets) {
  if (num_skills <= 0) throw InputError("expertise estimation", "the number of skills must be > 0");
  ExpertiseEstimate out;
  const auto skills = static_cast<std::size_t>(num_skills);
  out.expertise.assign(skills, 0.0);
  out.occurrences.assign(skills, 0);
  out.contributions.assign(skills, {});

  for (std::size_t t = 0; t < trials.size(); ++t) {
    const ExpertiseTrial& trial = trials[t];
    if (!std::isfinite(trial.student_reward) || trial.student_reward > 0.0) {
      throw InputError(trial_name(t, trial.scenario),
                       "student reward " + std::to_string(trial.student_reward) +
                           " must be finite and <= 0 (map task scores with non_positive_reward)");
    }
    check_skills(trial.expert, num_skills, t, trial.scenario, "expert");
    check_skills(trial.student, num_skills, t, trial.scenario, "student");

    std::set<int> student_skills;
    for (const auto& s : trial.student.segments) student_skills.insert(s.skill);

    int j = 1;  // 1-based: the paper's j ← 0 would divide the first skill's penalty by zero
    for (const auto& s : trial.expert.segments) {
      const auto m = static_cast<std::size_t>(s.skill);
      ++out.occurrences[m];
      if (student_skills.count(s.skill) == 0) {
        const double delta = -trial.student_reward / j;
        out.expertise[m] -= delta;
        out.contributions[m].push_back({static_cast<int>(t), trial.scenario, j, trial.student_reward, delta});
      }
      ++j;
    }
  }
  rank_expertise(out, num_targets);
  return out;
}

double non_positive_reward(double score, double best) {
  const double r = score - best;
  return r < 0.0 ? r : 0.0;
}

}  // namespace sc
