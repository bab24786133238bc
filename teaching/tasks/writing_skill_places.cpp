#include "teaching/tasks/writing_skill_places.hpp"

#include <algorithm>

#include "engine/writing/alphabet.hpp"

namespace sc {
namespace {

constexpr double kDominantShare = 0.6;

std::string part_words(char symbol, CharacterPart part) {
  if (writing::is_connector(symbol)) return std::string("the connector '") + symbol + "'";
  static const char* const kParts[] = {"the start of '", "the middle of '", "the end of '"};
  return kParts[static_cast<int>(part)] + std::string(1, symbol) + "'";
}

}  // namespace

int WordCharacters::symbol_at(int t) const {
  const auto it = std::upper_bound(character_starts.begin(), character_starts.end(), t);
  return std::max(0, static_cast<int>(it - character_starts.begin()) - 1);
}

double WritingSkillPlace::share_of(char symbol) const {
  const auto it = character_steps.find(symbol);
  return steps == 0 || it == character_steps.end() ? 0.0 : static_cast<double>(it->second) / steps;
}

std::vector<WritingSkillPlace> writing_skill_places(const std::vector<WordCharacters>& words,
                                                    const std::vector<Segmentation>& segmentations,
                                                    int num_skills) {
  std::vector<WritingSkillPlace> out(static_cast<std::size_t>(std::max(num_skills, 0)));
  for (std::size_t w = 0; w < words.size() && w < segmentations.size(); ++w) {
    const WordCharacters& word = words[w];
    if (word.character_starts.empty()) continue;
    for (const SkillSegment& seg : segmentations[w].segments) {
      if (seg.skill < 0 || seg.skill >= num_skills) continue;
      WritingSkillPlace& place = out[static_cast<std::size_t>(seg.skill)];
      for (int t = seg.begin; t < seg.end && t < word.length; ++t) {
        const int k = word.symbol_at(t);
        const char symbol = word.word[static_cast<std::size_t>(k)];
        const int begin = word.character_starts[static_cast<std::size_t>(k)];
        const int end = k + 1 < static_cast<int>(word.character_starts.size())
                            ? word.character_starts[static_cast<std::size_t>(k + 1)]
                            : word.length;
        // Connectors are short pen moves between characters: one place, no thirds.
        const int third = writing::is_connector(symbol) ? 0 : std::clamp(3 * (t - begin) / std::max(end - begin, 1), 0, 2);
        ++place.steps;
        ++place.character_steps[symbol];
        ++place.part_steps[{symbol, static_cast<CharacterPart>(third)}];
      }
    }
  }
  return out;
}

std::string describe_writing_place(const WritingSkillPlace& place) {
  if (place.steps == 0) return "unused skill";
  std::vector<std::pair<int, std::pair<char, CharacterPart>>> ranked;
  for (const auto& [key, n] : place.part_steps) ranked.push_back({n, key});
  // Most steps first; ties by symbol then part (deterministic).
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    return a.second < b.second;
  });
  const auto [symbol, part] = ranked[0].second;
  if (ranked.size() < 2 || ranked[0].first >= kDominantShare * place.steps) return part_words(symbol, part);
  const auto [symbol2, part2] = ranked[1].second;
  if (symbol2 == symbol && !writing::is_connector(symbol)) {
    // Two thirds of one character: "the start and middle of 'a'", in writing order.
    static const char* const kNames[] = {"start", "middle", "end"};
    const int a = std::min(static_cast<int>(part), static_cast<int>(part2));
    const int b = std::max(static_cast<int>(part), static_cast<int>(part2));
    return std::string("the ") + kNames[a] + " and " + kNames[b] + " of '" + symbol + "'";
  }
  return part_words(symbol, part) + " and " + part_words(symbol2, part2);
}

}  // namespace sc
