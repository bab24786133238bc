#include "teaching/curricula/teachable_skills.hpp"

#include <algorithm>
#include <map>

namespace sc {

bool is_teachable(int skill, const std::vector<Segmentation>& pool, int min_steps) {
  for (const auto& seg : pool) {
    for (const auto& s : seg.segments) {
      if (s.skill == skill && s.length() > 0 && s.length() >= min_steps) return true;
    }
  }
  return false;
}

std::vector<std::pair<int, int>> teachable_by_frequency(const std::vector<Segmentation>& pool, int min_steps) {
  std::map<int, int> counts;
  for (const auto& seg : pool) {
    for (const auto& s : seg.segments) {
      if (s.length() > 0 && s.length() >= min_steps) ++counts[s.skill];
    }
  }
  std::vector<std::pair<int, int>> out(counts.begin(), counts.end());  // ascending id
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

std::vector<int> teachable_ranking(const ExpertiseEstimate& diagnosis, const std::vector<Segmentation>& pool,
                                   int min_steps) {
  std::vector<int> out;
  for (int m : diagnosis.ranking) {
    if (is_teachable(m, pool, min_steps)) out.push_back(m);
  }
  return out;
}

}  // namespace sc
