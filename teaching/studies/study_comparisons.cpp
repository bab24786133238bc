#include "teaching/studies/study_comparisons.hpp"

#include <algorithm>

#include "teaching/curricula/study_condition.hpp"

namespace sc {
namespace {

using C = StudyCondition;

// The paper's pairs, the hypothesised better condition first.
constexpr std::pair<C, C> kPaperPairs[] = {
    {C::Skills, C::FullTrajectory}, {C::Skills, C::TimeHeuristic}, {C::TimeHeuristic, C::FullTrajectory},
    {C::Drills, C::Skills},         {C::IndDrills, C::Skills},     {C::IndDrills, C::Drills},
};

bool has(const std::vector<std::string>& conditions, C c) {
  return std::find(conditions.begin(), conditions.end(), condition_key(c)) != conditions.end();
}

std::vector<std::pair<std::string, std::string>> all_pairs(const std::vector<std::string>& conditions) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < conditions.size(); ++i)
    for (std::size_t j = i + 1; j < conditions.size(); ++j) out.emplace_back(conditions[i], conditions[j]);
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> planned_comparisons(const std::vector<std::string>& conditions,
                                                                     ComparisonPlan plan) {
  if (plan == ComparisonPlan::AllPairs) return all_pairs(conditions);
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [a, b] : kPaperPairs)
    if (has(conditions, a) && has(conditions, b)) out.emplace_back(condition_key(a), condition_key(b));
  const std::string adaptive(condition_key(C::Adaptive));
  if (has(conditions, C::Adaptive))
    for (const std::string& other : conditions)
      if (other != adaptive) out.emplace_back(adaptive, other);
  return out.empty() ? all_pairs(conditions) : out;
}

}  // namespace sc
