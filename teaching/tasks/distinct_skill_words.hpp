#pragma once
// Skill names a learner can tell apart: when several used skills get the same words, each gets a suffix
// of its own (parking: its pace, writing: its form), so two different skills never share one name.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sc {

// `words[i]` names skill i; `used[i]` says whether it occurs (unused skills keep their words). Skills that
// share words are ordered by `before` and renamed `rename(words, k, n)` for the k-th (0-based) of n.
std::vector<std::string> distinct_skill_words(
    std::vector<std::string> words, const std::vector<bool>& used,
    const std::function<bool(std::size_t, std::size_t)>& before,
    const std::function<std::string(const std::string&, std::size_t, std::size_t)>& rename);

}  // namespace sc
