// Repetition boundaries on the writing expert's words, scored like evaluate-skills (boundary F1 at +-5 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include "teaching/skills/repeat_boundaries.hpp"
#include "teaching/tasks/skill_quality.hpp"
#include "teaching/tasks/skill_training_data.hpp"

namespace sc {
namespace {

Segmentation segmentation_of(const std::vector<int>& boundaries, int length) {
  Segmentation s;
  int begin = 0;
  for (int b : boundaries) {
    s.segments.push_back({0, begin, b});
    begin = b;
  }
  s.segments.push_back({0, begin, length});
  return s;
}

TEST(RepeatBoundariesWriting, FindTheSymbolEdgesOfGeneratedWords) {
  const SkillDataSet data = generate_writing_demos(300, 0);
  const auto found = find_repeat_boundaries(data.steps());
  std::vector<Segmentation> predicted;
  for (std::size_t i = 0; i < found.size(); ++i)
    predicted.push_back(segmentation_of(found[i], data.demos[i].steps.length()));
  const BoundaryScore s = writing_boundary_score(predicted, data.demos);
  std::printf("P %.3f R %.3f F1 %.3f\n", s.precision(), s.recall(), s.f1());
  // Measured 0.980 (P = R: every word gets its 7 boundaries). The misses are positions inside a letter's
  // vertical lead-in, where letters with shorter lead-ins part from it, preferred over a true edge that
  // nothing in the corpus marks (e.g. "a-^" at the end of a word is always written the same way).
  EXPECT_GE(s.f1(), 0.95);
}

TEST(RepeatBoundariesWriting, UnitsOfGeneratedWordsAreOneIdPerSymbol) {
  const SkillDataSet data = generate_writing_demos(300, 0);
  const auto found = find_repeat_boundaries(data.steps());
  const auto units = repeat_units(data.steps(), found, 24);
  // Per true symbol, how its steps spread over the unit ids (-1 = no unit): each symbol should be mostly
  // one unit, and no unit mostly two symbols. Measured: 7 units for the 7 symbols, each symbol's unit
  // holding 0.92-1.00 of its steps except 'e' (0.75: its edges are where the boundaries miss most).
  std::map<char, std::map<int, int>> steps_of;
  for (std::size_t i = 0; i < found.size(); ++i) {
    const auto& truth = data.demos[i].true_boundaries;
    const std::string& word = data.demos[i].label;
    for (int t = 0; t < data.demos[i].steps.length(); ++t) {
      const auto symbol = std::upper_bound(truth.begin(), truth.end(), t) - truth.begin();
      const auto segment = std::upper_bound(found[i].begin(), found[i].end(), t) - found[i].begin();
      ++steps_of[word[static_cast<std::size_t>(symbol)]][units[i][static_cast<std::size_t>(segment)]];
    }
  }
  std::map<int, char> owner;
  for (const auto& [symbol, spread] : steps_of) {
    int total = 0, best = 0, best_unit = -1;
    for (const auto& [unit, n] : spread) {
      total += n;
      if (n > best) best = n, best_unit = unit;
    }
    std::printf("'%c': unit %d holds %.3f of its steps (%zu units)\n", symbol, best_unit,
                static_cast<double>(best) / total, spread.size());
    EXPECT_GE(best_unit, 0) << symbol;
    EXPECT_GE(static_cast<double>(best) / total, 0.7) << symbol;
    EXPECT_EQ(owner.count(best_unit), 0u)
        << "'" << symbol << "' and '" << owner[best_unit] << "' share unit " << best_unit;
    owner[best_unit] = symbol;
  }
}

}  // namespace
}  // namespace sc
