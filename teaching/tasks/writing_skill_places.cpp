#include "teaching/tasks/writing_skill_places.hpp"

#include <algorithm>

#include "engine/writing/alphabet.hpp"
#include "teaching/tasks/distinct_skill_words.hpp"

namespace sc {
namespace {

constexpr double kDominantShare = 0.6;

std::string part_words(char symbol, CharacterPart part) {
  if (writing::is_connector(symbol)) return std::string("the connector '") + symbol + "'";
  static const char* const kParts[] = {"the start of '", "the middle of '", "the end of '"};
  return kParts[static_cast<int>(part)] + std::string(1, symbol) + "'";
}

constexpr double kWholePartShare = 0.2;   // each third holds at least this share of the symbol's steps
constexpr double kWholeSkillShare = 0.8;  // the whole symbols named cover at least this share of the skill

// The symbol's steps in this skill, and whether they spread over all three thirds of it (a connector
// has no thirds: always whole).
bool covers_whole(const WritingSkillPlace& place, char symbol) {
  if (writing::is_connector(symbol)) return true;
  const int n = place.character_steps.at(symbol);
  for (int part = 0; part < 3; ++part) {
    const auto it = place.part_steps.find({symbol, static_cast<CharacterPart>(part)});
    if (it == place.part_steps.end() || it->second < kWholePartShare * n) return false;
  }
  return true;
}

// "the letter 'b'", "the letters 't' and 'c'", "the letter 'a' and the connector '^'": the whole symbols
// that make up most of the skill, most steps first; empty when the skill is mostly parts of symbols.
std::string whole_symbols_words(const WritingSkillPlace& place) {
  std::vector<std::pair<int, char>> ranked;
  for (const auto& [symbol, n] : place.character_steps) ranked.push_back({n, symbol});
  std::sort(ranked.begin(), ranked.end(),
            [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  std::vector<char> letters, connectors;
  int covered = 0;
  for (const auto& [n, symbol] : ranked) {
    if (covered >= kWholeSkillShare * place.steps || n < kWholePartShare * place.steps) break;
    if (!covers_whole(place, symbol)) return {};
    (writing::is_connector(symbol) ? connectors : letters).push_back(symbol);
    covered += n;
  }
  if (covered < kWholeSkillShare * place.steps) return {};
  auto list = [](const std::vector<char>& symbols, const std::string& one, const std::string& many) {
    if (symbols.empty()) return std::string();
    std::string text = "the " + (symbols.size() == 1 ? one : many) + " '" + symbols[0] + "'";
    for (std::size_t i = 1; i < symbols.size(); ++i)
      text += (i + 1 == symbols.size() ? " and '" : ", '") + std::string(1, symbols[i]) + "'";
    return text;
  };
  const std::string a = list(letters, "letter", "letters"), b = list(connectors, "connector", "connectors");
  return a.empty() ? b : (b.empty() ? a : a + " and " + b);
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
                                                    const std::vector<Segmentation>& segmentations, int num_skills) {
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
        const int third =
            writing::is_connector(symbol) ? 0 : std::clamp(3 * (t - begin) / std::max(end - begin, 1), 0, 2);
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
  if (const std::string whole = whole_symbols_words(place); !whole.empty()) return whole;
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

std::vector<std::string> describe_writing_places(const std::vector<WritingSkillPlace>& places) {
  std::vector<std::string> words;
  std::vector<bool> used;
  for (const auto& p : places) {
    words.push_back(describe_writing_place(p));
    used.push_back(p.steps > 0);
  }
  return distinct_skill_words(
      std::move(words), used, [&](std::size_t a, std::size_t b) { return places[a].steps > places[b].steps; },
      [](const std::string& text, std::size_t k, std::size_t n) {
        return text + ", form " + std::to_string(k + 1) + " of " + std::to_string(n);
      });
}

}  // namespace sc
