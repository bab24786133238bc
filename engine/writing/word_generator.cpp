#include "engine/writing/word_generator.hpp"

#include <algorithm>
#include <stdexcept>

namespace sc::writing {

const std::vector<WeightedNgram>& classic_sixgrams() {
  static const std::vector<WeightedNgram> table = {{"c-a-t-", .05}, {"b-a-t-", .20}, {"b-e-a-", .10}, {"t-e-a-", .10},
                                                   {"e-a-t-", .10}, {"a-t-^-", .10}, {"-e-a-^", .10}, {"--b-a-", .10},
                                                   {"-a--t-", .10}, {"-e-^a-", .05}};
  return table;
}

const std::vector<WeightedNgram>& classic_bigrams() {
  static const std::vector<WeightedNgram> table = {{"--", .4}, {"^-", .4}, {"c-", .2}};
  return table;
}

std::size_t draw_weighted(const std::vector<WeightedNgram>& table, Rng& rng) {
  if (table.empty()) throw std::invalid_argument("draw_weighted: empty table");
  const double u = rng.uniform();
  double cumulative = 0.0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    cumulative += table[i].probability;
    if (u < cumulative) return i;
  }
  return table.size() - 1;  // rounding: the cumulative sum may end a hair below 1
}

std::vector<std::string> generate_classic_words(int pairs, Rng& rng) {
  std::vector<std::string> words;
  words.reserve(2 * static_cast<std::size_t>(pairs > 0 ? pairs : 0));
  for (int i = 0; i < pairs; ++i) {
    // Four independent draws in the reference's order: sixgram, bigram, then bigram, sixgram.
    const auto six1 = classic_sixgrams()[draw_weighted(classic_sixgrams(), rng)].text;
    const auto two1 = classic_bigrams()[draw_weighted(classic_bigrams(), rng)].text;
    words.push_back(std::string(six1) + std::string(two1));
    const auto two2 = classic_bigrams()[draw_weighted(classic_bigrams(), rng)].text;
    const auto six2 = classic_sixgrams()[draw_weighted(classic_sixgrams(), rng)].text;
    words.push_back(std::string(two2) + std::string(six2));
  }
  return words;
}

std::vector<std::string> classic_words(int count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<std::string> words = generate_classic_words((std::max(count, 0) + 1) / 2, rng);
  words.resize(static_cast<std::size_t>(std::max(count, 0)));
  return words;
}

std::string generate_balinese_word(Rng& rng) {
  const int characters = 2 + static_cast<int>(rng.below(3));
  std::string word;
  for (int i = 0; i < characters; ++i) {
    if (i > 0) word.push_back(characters < 4 && rng.uniform() < 0.25 ? '^' : '-');
    word.push_back(static_cast<char>('A' + rng.below(kBalineseCharacters)));
  }
  return word;
}

}  // namespace sc::writing
