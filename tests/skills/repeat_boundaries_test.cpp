#include "teaching/skills/repeat_boundaries.hpp"

#include <gtest/gtest.h>

#include <random>

#include "engine/core/error.hpp"

namespace sc {
namespace {

using Symbol = std::vector<float>;  // 2-D actions, flattened

// `count` symbols of 30..59 random steps each, drawn from a small set of step values (as pen steps are).
std::vector<Symbol> random_symbols(int count, std::mt19937& rng) {
  std::uniform_int_distribution<int> length(30, 59), value(-2, 2);
  std::vector<Symbol> out(static_cast<std::size_t>(count));
  for (auto& s : out)
    for (int t = 0, n = length(rng); t < n; ++t) {
      s.push_back(static_cast<float>(value(rng)) * 0.5f);
      s.push_back(static_cast<float>(value(rng)) * 0.5f);
    }
  return out;
}

struct Word {
  StepSequence steps;
  std::vector<int> boundaries;
};

Word concatenate(const std::vector<Symbol>& symbols, const std::vector<int>& order) {
  Word w;
  w.steps.action_dim = 2;
  for (int i : order) {
    if (!w.steps.actions.empty()) w.boundaries.push_back(w.steps.length());
    const Symbol& s = symbols[static_cast<std::size_t>(i)];
    w.steps.actions.insert(w.steps.actions.end(), s.begin(), s.end());
  }
  return w;
}

TEST(RepeatBoundaries, FindEveryEdgeOfSymbolsThatOccurInSeveralContexts) {
  std::mt19937 rng(7);
  const auto symbols = random_symbols(5, rng);
  std::uniform_int_distribution<int> pick(0, 4);
  std::vector<Word> words;
  std::vector<StepSequence> demos;
  for (int i = 0; i < 60; ++i) {
    std::vector<int> order;
    for (int j = 0; j < 4; ++j) order.push_back(pick(rng));
    words.push_back(concatenate(symbols, order));
    demos.push_back(words.back().steps);
  }
  RepeatBoundaryConfig config;
  config.context = 16;
  config.max_boundaries = 3;
  const auto found = find_repeat_boundaries(demos, config);
  ASSERT_EQ(found.size(), words.size());
  for (std::size_t i = 0; i < words.size(); ++i) EXPECT_EQ(found[i], words[i].boundaries) << "word " << i;
}

TEST(RepeatBoundaries, ASymbolAlwaysFollowedByTheSameOneIsOnePiece) {
  // "0 1" always appear together: nothing in the data tells them apart, so no boundary between them.
  std::mt19937 rng(3);
  const auto symbols = random_symbols(3, rng);
  const std::vector<StepSequence> demos = {concatenate(symbols, {0, 1, 2}).steps, concatenate(symbols, {2, 0, 1}).steps,
                                           concatenate(symbols, {2, 2, 0, 1}).steps};
  RepeatBoundaryConfig config;
  config.context = 16;
  const auto found = find_repeat_boundaries(demos, config);
  const int len0 = static_cast<int>(symbols[0].size()) / 2, len1 = static_cast<int>(symbols[1].size()) / 2;
  const int len2 = static_cast<int>(symbols[2].size()) / 2;
  EXPECT_EQ(found[0], (std::vector<int>{len0 + len1}));
  EXPECT_EQ(found[1], (std::vector<int>{len2}));
  EXPECT_EQ(found[2], (std::vector<int>{len2, 2 * len2}));
}

TEST(RepeatBoundaries, ContinuousActionsThatNeverRepeatGiveNone) {
  std::mt19937 rng(11);
  std::normal_distribution<float> noise(0.0f, 1.0f);
  std::vector<StepSequence> demos(4);
  for (auto& d : demos) {
    d.action_dim = 2;
    for (int t = 0; t < 200; ++t) d.actions.push_back(noise(rng)), d.actions.push_back(noise(rng));
  }
  for (const auto& f : find_repeat_boundaries(demos)) EXPECT_TRUE(f.empty());
}

TEST(RepeatBoundaries, KeepsAtMostMaxBoundariesAtLeastMinSeparationApart) {
  std::mt19937 rng(5);
  const auto symbols = random_symbols(4, rng);
  std::vector<StepSequence> demos;
  for (int i = 0; i < 40; ++i)
    demos.push_back(concatenate(symbols, {i % 4, (i / 4) % 4, (i / 16) % 4, i % 3, (i + 1) % 4}).steps);
  RepeatBoundaryConfig config;
  config.context = 16;
  config.max_boundaries = 2;
  config.min_separation = 25;
  for (const auto& f : find_repeat_boundaries(demos, config)) {
    EXPECT_LE(f.size(), 2u);
    for (std::size_t j = 1; j < f.size(); ++j) EXPECT_GE(f[j] - f[j - 1], 25);
  }
}

TEST(RepeatUnits, EqualSegmentsShareAnIdByFrequencyAndSingletonsGetNone) {
  std::mt19937 rng(13);
  const auto symbols = random_symbols(4, rng);
  // Symbol 0 three times, 1 twice, 2 once, 3 once (the last two never repeat).
  const std::vector<Word> words = {concatenate(symbols, {1, 0}), concatenate(symbols, {0, 2}),
                                   concatenate(symbols, {1, 0, 3})};
  std::vector<StepSequence> demos;
  std::vector<std::vector<int>> boundaries;
  for (const auto& w : words) demos.push_back(w.steps), boundaries.push_back(w.boundaries);
  const auto units = repeat_units(demos, boundaries, 8);
  EXPECT_EQ(units, (std::vector<std::vector<int>>{{1, 0}, {0, -1}, {1, 0, -1}}));
  // Only the most frequent unit when one id is allowed.
  EXPECT_EQ(repeat_units(demos, boundaries, 1), (std::vector<std::vector<int>>{{-1, 0}, {0, -1}, {-1, 0, -1}}));
  // A slightly different copy of symbol 0 is not the same unit.
  demos[1].actions[0] += 0.01f;
  EXPECT_EQ(repeat_units(demos, boundaries, 8)[1][0], -1);
  EXPECT_THROW(repeat_units(demos, {{}}, 8), InputError);
  EXPECT_THROW(repeat_units(demos, {{5, 2}, {}, {}}, 8), InputError);
}

TEST(RepeatBoundaries, RejectsAConfigOutOfRange) {
  RepeatBoundaryConfig config;
  config.context = 0;
  EXPECT_THROW(find_repeat_boundaries({}, config), InputError);
}

}  // namespace
}  // namespace sc
