#pragma once
// Where a writing skill is used, from the TRUE character boundaries of the expert words: how many expert
// pen steps of each character (and of which third of it: start, middle, end) carry the skill, and the
// plain words for it ("the start of 'b'", "the middle of 'a' and the end of 't'").
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

enum class CharacterPart { Start = 0, Middle = 1, End = 2 };

// One expert word with its character boundaries (WordTrajectory::character_starts).
struct WordCharacters {
  std::string word;
  std::vector<int> character_starts;  // one per symbol of word, increasing, first = 0
  int length = 0;                     // pen steps of the whole word
  // The symbol index of step t (the last symbol whose start <= t).
  int symbol_at(int t) const;
};

struct WritingSkillPlace {
  int steps = 0;                                             // expert pen steps carrying the skill
  std::map<char, int> character_steps;                       // per symbol
  std::map<std::pair<char, CharacterPart>, int> part_steps;  // per symbol and third of it
  // The share of the skill's steps inside `symbol` (0 when the skill is unused).
  double share_of(char symbol) const;
};

std::vector<WritingSkillPlace> writing_skill_places(const std::vector<WordCharacters>& words,
                                                    const std::vector<Segmentation>& segmentations, int num_skills);

// The most used (symbol, part), plus the second when the first covers under 60 % of the skill's steps.
// Connectors are named as such ("the connector '-'").
std::string describe_writing_place(const WritingSkillPlace& place);
// The words of every skill, distinct among used skills: skills that share words get ", form k of n" added,
// the most used first, so a learner never sees two different skills under one name.
std::vector<std::string> describe_writing_places(const std::vector<WritingSkillPlace>& places);

}  // namespace sc
