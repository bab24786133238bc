#pragma once
// Training/practice words.
//  * classic: the reference's generator (§2.6): each iteration yields TWO 8-symbol words, (sixgram + bigram)
//    then (bigram + sixgram), all four n-grams drawn independently from fixed distributions. Seeded with sc::Rng, so
//    the distribution matches the reference but not numpy's stream.
//  * balinese (our extension): 2..4 random characters A..X joined by connectors ('-' 3/4, '^' 1/4); words
//    with 4 characters use '-' only so that they fit the 500 px canvas.
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/writing/alphabet.hpp"

namespace sc::writing {

struct WeightedNgram {
  std::string_view text;
  double probability;
};
// The reference's tables, in its order (probabilities sum to 1).
const std::vector<WeightedNgram>& classic_sixgrams();
const std::vector<WeightedNgram>& classic_bigrams();

// Draws an index with probability table[i].probability (cumulative search on one uniform, like numpy).
std::size_t draw_weighted(const std::vector<WeightedNgram>& table, Rng& rng);

// `pairs` draws -> 2 * pairs words; the reference used pairs = 1000 with numpy seed 0.
std::vector<std::string> generate_classic_words(int pairs, Rng& rng);
// The first `count` words of generate_classic_words from Rng(seed): THE generated words of a seed, shared by
// train-skills/evaluate-skills (their demonstrations) and `expert --task writing` (their trial files).
std::vector<std::string> classic_words(int count, std::uint64_t seed);
std::string generate_balinese_word(Rng& rng);

}  // namespace sc::writing
