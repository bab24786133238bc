#include "teaching/drills/skill_ngrams.hpp"

#include <algorithm>
#include <map>

#include "engine/core/error.hpp"

namespace sc {

bool SkillNgram::contains(int skill) const { return std::find(skills.begin(), skills.end(), skill) != skills.end(); }

SkillNgramTable::SkillNgramTable(const std::vector<Segmentation>& expert_pool, int n) : n_(n) {
  if (n < 1) throw InputError("skill n-grams", "n must be >= 1, got " + std::to_string(n));
  std::map<std::vector<int>, int> counts;
  const auto width = static_cast<std::size_t>(n);
  for (const auto& seg : expert_pool) {
    const std::vector<int> ids = seg.skills();
    if (ids.empty()) continue;
    if (ids.size() < width) {
      ++counts[ids];  // short sequence: the whole sequence is one gram (see header)
      continue;
    }
    for (std::size_t i = 0; i + width <= ids.size(); ++i) {
      ++counts[std::vector<int>(ids.begin() + static_cast<long>(i), ids.begin() + static_cast<long>(i + width))];
    }
  }
  grams_.reserve(counts.size());
  for (auto& [skills, count] : counts) grams_.push_back({skills, count});
  // std::map already orders lexicographically; a stable sort keeps that as the last tie-break.
  std::stable_sort(grams_.begin(), grams_.end(), [](const SkillNgram& a, const SkillNgram& b) {
    if (a.count != b.count) return a.count > b.count;
    return a.skills.size() > b.skills.size();
  });
}

int SkillNgramTable::frequency(const std::vector<int>& skills) const {
  for (const auto& g : grams_) {
    if (g.skills == skills) return g.count;
  }
  return 0;
}

std::vector<SkillNgram> SkillNgramTable::most_frequent_containing(int skill, int k,
                                                                  const std::vector<std::vector<int>>& skip) const {
  std::vector<SkillNgram> out;
  for (const auto& g : grams_) {
    if (static_cast<int>(out.size()) >= k) break;
    if (!g.contains(skill)) continue;
    if (std::find(skip.begin(), skip.end(), g.skills) != skip.end()) continue;
    out.push_back(g);
  }
  return out;
}

}  // namespace sc
