#pragma once
// A word written by the expert: the glyphs' relative steps chained from the start (0, 150) (reference
// §2.5: the next symbol starts where the previous one ended; classic words never lift the pen).
#include <string>
#include <string_view>
#include <vector>

#include "engine/writing/alphabet.hpp"

namespace sc::writing {

inline constexpr int kMaxWordSymbols = 10;  // DRAWING_MAX_TRAJ: length of the goal vector

struct WordTrajectory {
  std::string word;
  AlphabetKind alphabet = AlphabetKind::Classic;
  Point2 start{kStartX, kStartY};
  std::vector<WritingStep> steps;
  std::vector<int> character_starts;  // step index where each symbol of `word` begins (one per symbol)
  std::vector<int> goal;              // kMaxWordSymbols symbol indices, -1 after the end of the word

  // start followed by the position after every step (steps.size() + 1 points), accumulated in double in
  // the reference's order; points[i + 1].pen = steps[i].pen.
  std::vector<TracePoint> points() const;
};

// Throws InputError(where, ...) unless the word has 1..10 symbols, all in the alphabet.
void validate_word(AlphabetKind kind, std::string_view word, std::string_view where);
// The same check returning the problem, or an empty string for a valid word.
std::string word_problem(AlphabetKind kind, std::string_view word);
std::vector<int> goal_vector(AlphabetKind kind, std::string_view word);

WordTrajectory build_word_trajectory(const GlyphSet& glyphs, std::string_view word);

}  // namespace sc::writing
