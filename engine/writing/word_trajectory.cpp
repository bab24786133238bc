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

std::string word_problem(AlphabetKind kind, std::string_view word) {
  if (word.empty()) return "empty word";
  if (word.size() > static_cast<std::size_t>(kMaxWordSymbols))
    return "word \"" + std::string(word) + "\" has " + std::to_string(word.size()) + " symbols; at most " +
           std::to_string(kMaxWordSymbols) + " fit the goal vector";
  for (char c : word) {
    if (symbol_index(kind, c) >= 0) continue;
    // Built with append: GCC 12's -Wrestrict misfires on a chain of operator+ here.
    std::string problem = "'";
    problem.push_back(c);
    problem.append("' is not a symbol of the ").append(alphabet_name(kind));
    problem.append(" alphabet (valid: ").append(alphabet_symbols(kind)).append(")");
    return problem;
  }
  return {};
}

void validate_word(AlphabetKind kind, std::string_view word, std::string_view where) {
  if (auto problem = word_problem(kind, word); !problem.empty()) throw InputError(where, problem);
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
