#include "teaching/tasks/distinct_skill_words.hpp"

#include <algorithm>
#include <map>

namespace sc {

std::vector<std::string> distinct_skill_words(
    std::vector<std::string> words, const std::vector<bool>& used,
    const std::function<bool(std::size_t, std::size_t)>& before,
    const std::function<std::string(const std::string&, std::size_t, std::size_t)>& rename) {
  std::map<std::string, std::vector<std::size_t>> groups;  // shared words -> skills, used ones only
  for (std::size_t i = 0; i < words.size() && i < used.size(); ++i)
    if (used[i]) groups[words[i]].push_back(i);
  for (auto& [text, skills] : groups) {
    if (skills.size() < 2) continue;
    std::stable_sort(skills.begin(), skills.end(), before);
    for (std::size_t k = 0; k < skills.size(); ++k) words[skills[k]] = rename(text, k, skills.size());
  }
  return words;
}

}  // namespace sc
