#include "engine/writing/word_trajectory.hpp"

#include "engine/core/error.hpp"

namespace sc::writing {

std::vector<TracePoint> WordTrajectory::points() const {
  std::vector<TracePoint> pts;
  pts.reserve(steps.size() + 1);
  double x = start.x, y = start.y;
  pts.push_back({x, y, steps.empty() ? true : steps.front().pen});
  for (const auto& s : steps) {
    x = x + s.dx;
    y = y + s.dy;
    pts.push_back({x, y, s.pen});
  }
  return pts;
}

void validate_word(AlphabetKind kind, std::string_view word, std::string_view where) {
  if (word.empty()) throw InputError(where, "empty word");
  if (word.size() > static_cast<std::size_t>(kMaxWordSymbols))
    throw InputError(where, "word \"" + std::string(word) + "\" has " + std::to_string(word.size()) +
                                " symbols; at most " + std::to_string(kMaxWordSymbols) + " fit the goal vector");
  for (char c : word)
    if (symbol_index(kind, c) < 0)
      throw InputError(where, "'" + std::string(1, c) + "' is not a symbol of the " + std::string(alphabet_name(kind)) +
                                  " alphabet (valid: " + std::string(alphabet_symbols(kind)) + ")");
}

std::vector<int> goal_vector(AlphabetKind kind, std::string_view word) {
  std::vector<int> goal(kMaxWordSymbols, -1);
  for (std::size_t i = 0; i < word.size() && i < goal.size(); ++i) goal[i] = symbol_index(kind, word[i]);
  return goal;
}

WordTrajectory build_word_trajectory(const GlyphSet& glyphs, std::string_view word) {
  validate_word(glyphs.kind(), word, "word");
  WordTrajectory traj;
  traj.word = std::string(word);
  traj.alphabet = glyphs.kind();
  traj.goal = goal_vector(glyphs.kind(), word);
  for (char c : word) {
    traj.character_starts.push_back(static_cast<int>(traj.steps.size()));
    const auto& steps = glyphs.glyph(c).steps;
    traj.steps.insert(traj.steps.end(), steps.begin(), steps.end());
  }
  return traj;
}

}  // namespace sc::writing
