#include "teaching/tasks/writing_cross_hand.hpp"

#include "engine/core/rng.hpp"
#include "engine/writing/word_generator.hpp"
#include "teaching/tasks/writing_execution.hpp"
#include "teaching/tasks/writing_other_hand.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

constexpr int kNoStep = -2;  // a clean step the alignment pairs with no copy step (never a skill, nor -1)

std::vector<writing::TracePoint> step_positions(const StepSequence& steps) {
  std::vector<writing::TracePoint> out;
  for (const TracePoint3& p : writing_trace_points(steps)) out.push_back({p[0], p[1], true});
  return out;
}

std::vector<int> skill_per_step(const Segmentation& segmentation, int length) {
  std::vector<int> out(static_cast<std::size_t>(length), -1);
  for (const SkillSegment& s : segmentation.segments)
    for (int t = std::max(s.begin, 0); t < s.end && t < length; ++t) out[static_cast<std::size_t>(t)] = s.skill;
  return out;
}

// The copies of `words` by drawers of `drawers`, against the clean words' steps and skills.
CrossHandConsistency consistency_with(const SkillExtractor& extractor, const ClassicDrawerGlyphs& glyphs,
                                      const std::vector<std::string>& words, std::uint64_t seed,
                                      const std::vector<int>& drawers, const std::vector<StepSequence>& clean,
                                      const std::vector<Segmentation>& clean_skills) {
  RealisticHand other;
  other.mouse = false;
  other.drawer_pool = drawers;
  std::vector<StepSequence> copies;
  const Rng root(seed);
  for (std::size_t i = 0; i < words.size(); ++i)
    copies.push_back(writing_step_sequence(realistic_trace(glyphs, words[i], other, root.fork(i).next_u64()).trace,
                                           writing::AlphabetKind::Classic, words[i]));
  const std::vector<Segmentation> copy_skills = extractor.extract_all(copies);
  CrossHandConsistency out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (clean[i].length() == 0 || copies[i].length() == 0) continue;
    const std::vector<int> want = skill_per_step(clean_skills[i], clean[i].length());
    const std::vector<int> got = skill_per_step(copy_skills[i], copies[i].length());
    const StepAlignment path = align_same_word(step_positions(clean[i]), step_positions(copies[i]));
    for (int t = 0; t < clean[i].length(); ++t) {
      const int j = aligned_span(path, t, t + 1).first;
      const int copy_skill = j >= 0 && j < copies[i].length() ? got[static_cast<std::size_t>(j)] : kNoStep;
      ++out.steps;
      out.agreeing += want[static_cast<std::size_t>(t)] == copy_skill;
      ++out.clean_skills[want[static_cast<std::size_t>(t)]];
      ++out.copy_skills[copy_skill];
    }
  }
  return out;
}

}  // namespace

std::vector<CrossHandConsistency> cross_hand_consistency(const SkillExtractor& extractor,
                                                         const ClassicDrawerGlyphs& glyphs,
                                                         const std::vector<std::string>& words, std::uint64_t seed,
                                                         const std::vector<std::vector<int>>& pools) {
  std::vector<StepSequence> clean;
  for (const std::string& word : words)
    clean.push_back(
        writing_step_sequence(unsampled(written_word(glyphs, word)).trace, writing::AlphabetKind::Classic, word));
  const std::vector<Segmentation> clean_skills = extractor.extract_all(clean);
  std::vector<CrossHandConsistency> out;
  for (const std::vector<int>& drawers : pools)
    out.push_back(consistency_with(extractor, glyphs, words, seed, drawers, clean, clean_skills));
  return out;
}

double CrossHandConsistency::kappa() const {
  if (steps == 0) return 0.0;
  double chance = 0.0;
  for (const auto& [skill, count] : clean_skills) {
    const auto copy = copy_skills.find(skill);
    if (copy != copy_skills.end()) chance += static_cast<double>(count) * copy->second;
  }
  chance /= static_cast<double>(steps) * steps;
  return chance >= 1.0 ? 0.0 : (share() - chance) / (1.0 - chance);
}

std::string RestartCrossHandCheck::describe() const {
  return "cross-hand consistency (kappa), drawers 1-10, " + std::to_string(words) + " classic words of seed " +
         std::to_string(seed);
}

RestartCrossHandCheck restart_cross_hand_check(std::uint64_t training_seed, int words) {
  RestartCrossHandCheck check;
  check.words = words;
  check.seed = Rng(training_seed).fork(kRestartCheckStream).next_u64();
  return check;
}

double restart_cross_hand_score(const SkillExtractor& extractor, const ClassicDrawerGlyphs& glyphs,
                                const RestartCrossHandCheck& check) {
  const std::vector<std::string> words = writing::classic_words(check.words, check.seed);
  return cross_hand_consistency(extractor, glyphs, words, check.seed, {training_drawers()}).front().kappa();
}

}  // namespace sc
