#include "engine/writing/word_generator.hpp"

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

namespace sc::writing {
namespace {

double sum_of(const std::vector<WeightedNgram>& t) {
  double s = 0;
  for (const auto& e : t) s += e.probability;
  return s;
}

TEST(ClassicWordGenerator, TablesAreTheReferences) {
  EXPECT_EQ(classic_sixgrams().size(), 10u);
  EXPECT_EQ(classic_bigrams().size(), 3u);
  EXPECT_NEAR(sum_of(classic_sixgrams()), 1.0, 1e-12);
  EXPECT_NEAR(sum_of(classic_bigrams()), 1.0, 1e-12);
  EXPECT_EQ(classic_sixgrams()[1].text, "b-a-t-");
  EXPECT_EQ(classic_sixgrams()[1].probability, 0.20);
}

TEST(ClassicWordGenerator, ShapeAndDistribution) {
  Rng rng(0);
  const int pairs = 20000;
  const auto words = generate_classic_words(pairs, rng);
  ASSERT_EQ(words.size(), 2u * pairs);
  std::map<std::string, int> six_counts, two_counts;
  for (std::size_t i = 0; i < words.size(); ++i) {
    ASSERT_EQ(words[i].size(), 8u);
    const bool six_first = i % 2 == 0;  // even: sixgram + bigram, odd: bigram + sixgram
    ++six_counts[six_first ? words[i].substr(0, 6) : words[i].substr(2)];
    ++two_counts[six_first ? words[i].substr(6) : words[i].substr(0, 2)];
  }
  const double n = static_cast<double>(words.size());
  for (const auto& e : classic_sixgrams()) {
    const double p = e.probability, sigma = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(six_counts[std::string(e.text)] / n, p, 4 * sigma) << e.text;
  }
  for (const auto& e : classic_bigrams()) {
    const double p = e.probability, sigma = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(two_counts[std::string(e.text)] / n, p, 4 * sigma) << e.text;
  }
  // The two words of a pair are drawn independently (the reference's first pair shares n-grams, its second
  // does not): how often both words use the same sixgram = sum p^2 = 0.12.
  int same = 0;
  for (std::size_t i = 0; i + 1 < words.size(); i += 2) same += words[i].substr(0, 6) == words[i + 1].substr(2);
  EXPECT_NEAR(same / static_cast<double>(pairs), 0.12, 0.012);
}

TEST(ClassicWordGenerator, SymbolTotalsMatchTheReferenceProportions) {
  // Reference 2000 words: '-' 9217, a 2000, ^ 1276, t 1258, e 913, b 833, c 503 (of 16000 symbols).
  Rng rng(1);
  std::map<char, double> counts;
  const auto words = generate_classic_words(50000, rng);
  for (const auto& w : words)
    for (char c : w) counts[c] += 1;
  const double total = 8.0 * static_cast<double>(words.size());
  const std::map<char, double> expected{{'-', 9217}, {'a', 2000}, {'^', 1276}, {'t', 1258},
                                        {'e', 913},  {'b', 833},  {'c', 503}};
  for (const auto& [c, ref] : expected) EXPECT_NEAR(counts[c] / total, ref / 16000.0, 0.01) << c;
  // 'a' appears exactly once in every word (every sixgram has one 'a', bigrams none).
  EXPECT_EQ(counts['a'], static_cast<double>(words.size()));
}

TEST(ClassicWordGenerator, SeededAndDeterministic) {
  Rng a(5), b(5), c(6);
  EXPECT_EQ(generate_classic_words(50, a), generate_classic_words(50, b));
  Rng d(5);
  EXPECT_NE(generate_classic_words(50, d), generate_classic_words(50, c));
}

TEST(BalineseWordGenerator, LengthsAndSymbols) {
  Rng rng(2);
  std::map<int, int> lengths;
  for (int i = 0; i < 3000; ++i) {
    const std::string w = generate_balinese_word(rng);
    const int characters = static_cast<int>(w.size() + 1) / 2;
    ++lengths[characters];
    for (std::size_t k = 0; k < w.size(); ++k) {
      if (k % 2 == 0) {
        EXPECT_TRUE(w[k] >= 'A' && w[k] <= 'X') << w;
      } else {
        EXPECT_TRUE(w[k] == '-' || (w[k] == '^' && characters < 4)) << w;
      }
    }
  }
  EXPECT_EQ(lengths.size(), 3u);
  for (int k = 2; k <= 4; ++k) EXPECT_NEAR(lengths[k] / 3000.0, 1.0 / 3.0, 0.04);
}

TEST(ClassicWordGenerator, ClassicWordsOfASeedAreTheFirstWordsOfItsStream) {
  Rng rng(7);
  const std::vector<std::string> stream = generate_classic_words(3, rng);  // 6 words
  EXPECT_EQ(classic_words(6, 7), stream);
  EXPECT_EQ(classic_words(5, 7), std::vector<std::string>(stream.begin(), stream.begin() + 5));  // odd count
  EXPECT_TRUE(classic_words(0, 7).empty());
  EXPECT_NE(classic_words(6, 8), stream);
}

}  // namespace
}  // namespace sc::writing
