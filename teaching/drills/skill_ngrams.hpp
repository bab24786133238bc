#pragma once
// n-gram frequencies of expert skill sequences (Eq. 4 of the paper), the raw material of drills (Alg. 3):
// f(x) = number of places where the n consecutive skills x occur in the expert skill sequences.
//
// Extension: a non-empty sequence shorter than n contributes itself once, as a shorter gram. Eq. 4 would
// ignore it, but parking experts often need only 1-2 skills (e.g. "forward-right then stop"), and with
// n = 3 a skill used only in such short episodes would otherwise get no drill at all.
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct SkillNgram {
  std::vector<int> skills;  // n skills (fewer for a short-sequence gram)
  int count = 0;            // f(x)
  bool contains(int skill) const;
  bool operator==(const SkillNgram&) const = default;
};

class SkillNgramTable {
 public:
  // Throws InputError when n < 1.
  SkillNgramTable(const std::vector<Segmentation>& expert_pool, int n);

  int n() const { return n_; }
  // Every distinct gram, most frequent first. Ties: full-length n-grams before shorter ones, then
  // lexicographically smaller skill sequence first (deterministic).
  const std::vector<SkillNgram>& grams() const { return grams_; }
  int frequency(const std::vector<int>& skills) const;  // 0 when absent
  // The k most frequent grams containing `skill`, in the order of grams(); `skip` lists grams to pass
  // over (used to keep drills of different target skills distinct).
  std::vector<SkillNgram> most_frequent_containing(int skill, int k,
                                                   const std::vector<std::vector<int>>& skip = {}) const;

 private:
  int n_;
  std::vector<SkillNgram> grams_;
};

}  // namespace sc
