#include "teaching/tasks/writing_cross_hand.hpp"

#include "engine/core/rng.hpp"
#include "engine/writing/word_generator.hpp"
#include "teaching/tasks/writing_execution.hpp"
#include "teaching/tasks/writing_other_hand.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

constexpr int kNoStep = -2;  // a clean step the alignment pairs with no copy step (never a skill, nor -1)

std::vector<int> skill_per_step(const Segmentation& segmentation, int length) {
  std::vector<int> out(static_cast<std::size_t>(length), -1);
  for (const SkillSegment& s : segmentation.segments)
    for (int t = std::max(s.begin, 0); t < s.end && t < length; ++t) out[static_cast<std::size_t>(t)] = s.skill;
  return out;
}

}  // namespace

CrossHandWords::CrossHandWords(const ClassicDrawerGlyphs& glyphs, const std::vector<std::string>& words,
                               std::uint64_t seed, const std::vector<std::vector<int>>& pools) {
  for (const std::string& word : words)
    clean_.push_back(
        writing_step_sequence(unsampled(written_word(glyphs, word)).trace, writing::AlphabetKind::Classic, word));
  const Rng root(seed);
  for (const std::vector<int>& drawers : pools) {
    RealisticHand other;
    other.mouse = false;
    other.drawer_pool = drawers;
    Pool pool;
    for (std::size_t i = 0; i < words.size(); ++i) {
      pool.copies.push_back(
          writing_step_sequence(realistic_trace(glyphs, words[i], other, root.fork(i).next_u64()).trace,
                                writing::AlphabetKind::Classic, words[i]));
      pool.paths.push_back(align_same_word(clean_[i], pool.copies[i]));
    }
    pools_.push_back(std::move(pool));
  }
}

std::vector<CrossHandConsistency> CrossHandWords::measure(const SkillExtractor& extractor) const {
  const std::vector<Segmentation> clean_skills = extractor.extract_all(clean_);
  std::vector<CrossHandConsistency> out;
  for (const Pool& pool : pools_) {
    const std::vector<Segmentation> copy_skills = extractor.extract_all(pool.copies);
    CrossHandConsistency c;
    for (std::size_t i = 0; i < clean_.size(); ++i) {
      if (clean_[i].length() == 0 || pool.copies[i].length() == 0) continue;
      const std::vector<int> want = skill_per_step(clean_skills[i], clean_[i].length());
      const std::vector<int> got = skill_per_step(copy_skills[i], pool.copies[i].length());
      for (int t = 0; t < clean_[i].length(); ++t) {
        const int j = aligned_span(pool.paths[i], t, t + 1).first;
        const int copy_skill = j >= 0 && j < pool.copies[i].length() ? got[static_cast<std::size_t>(j)] : kNoStep;
        ++c.steps;
        c.agreeing += want[static_cast<std::size_t>(t)] == copy_skill;
        ++c.clean_skills[want[static_cast<std::size_t>(t)]];
        ++c.copy_skills[copy_skill];
      }
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<CrossHandConsistency> cross_hand_consistency(const SkillExtractor& extractor,
                                                         const ClassicDrawerGlyphs& glyphs,
                                                         const std::vector<std::string>& words, std::uint64_t seed,
                                                         const std::vector<std::vector<int>>& pools) {
  return CrossHandWords(glyphs, words, seed, pools).measure(extractor);
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

CrossHandWords restart_check_words(const ClassicDrawerGlyphs& glyphs, const RestartCrossHandCheck& check) {
  return CrossHandWords(glyphs, writing::classic_words(check.words, check.seed), check.seed, {training_drawers()});
}

double restart_cross_hand_score(const SkillExtractor& extractor, const CrossHandWords& check_words) {
  return check_words.measure(extractor).front().kappa();
}

}  // namespace sc
