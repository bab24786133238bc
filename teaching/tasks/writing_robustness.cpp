#include "teaching/tasks/writing_robustness.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "engine/writing/step_data.hpp"
#include "teaching/tasks/skill_quality.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

RealisticHand hand(double wobble_px, double affine, std::vector<int> drawers, double hesitations) {
  RealisticHand h;
  h.noise = {wobble_px, affine};
  h.drawer_pool = std::move(drawers);
  h.sampling.hesitations_per_letter = hesitations;
  return h;
}

RealisticHand without_mouse(RealisticHand h) {
  h.mouse = false;
  return h;
}

// Symbol ranges [starts[k], starts[k + 1]) of a sequence of `length` actions.
int range_end(const std::vector<int>& starts, std::size_t k, int length) {
  return k + 1 < starts.size() ? starts[k + 1] : length;
}

}  // namespace

std::vector<WritingCondition> writing_robustness_conditions() {
  RealisticHand mouse_only = hand(0.0, 0.0, {}, 0.0);
  return {{"expert gold", std::nullopt},
          {"mouse sampling", mouse_only},
          {"wobble 5 px", hand(5.0, 0.0, {}, 0.0)},
          {"wobble 10 px", hand(10.0, 0.0, {}, 0.0)},
          {"unseen drawers 11-15", hand(0.0, 0.0, unseen_drawers(), 0.0)},
          {"realistic: unseen drawers, 5 px, affine 0.1, hesitations", hand(5.0, 0.1, unseen_drawers(), 0.3)},
          {"wobble 5 px, no mouse sampling", without_mouse(hand(5.0, 0.0, {}, 0.0))},
          {"affine 0.1 per letter, no mouse sampling", without_mouse(hand(0.0, 0.1, {}, 0.0))},
          {"training drawers 1-10, no mouse sampling", without_mouse(hand(0.0, 0.0, training_drawers(), 0.0))}};
}

int majority_skill(const Segmentation& segmentation, int begin, int end) {
  std::map<int, int> steps;
  for (const SkillSegment& s : segmentation.segments) {
    const int overlap = std::min(end, s.end) - std::max(begin, s.begin);
    if (overlap > 0) steps[s.skill] += overlap;
  }
  int best = -1, most = 0;
  for (const auto& [skill, n] : steps)
    if (n > most) best = skill, most = n;
  return best;
}

std::vector<WritingRobustnessRow> measure_writing_robustness(const SkillExtractor& extractor,
                                                             const ClassicDrawerGlyphs& glyphs,
                                                             const std::vector<std::string>& words, std::uint64_t seed,
                                                             const std::vector<WritingCondition>& conditions) {
  std::vector<WrittenWord> golds;
  std::vector<StepSequence> gold_steps;
  for (const std::string& w : words) {
    golds.push_back(written_word(glyphs, w));
    gold_steps.push_back(writing_step_sequence(unsampled(golds.back()).trace, writing::AlphabetKind::Classic, w));
  }
  const std::vector<Segmentation> expert = extractor.extract_all(gold_steps);
  const Rng root(seed);
  std::vector<WritingRobustnessRow> rows;
  for (const WritingCondition& condition : conditions) {
    std::vector<SkillDemo> demos;
    std::vector<std::vector<int>> starts;
    for (std::size_t i = 0; i < words.size(); ++i) {
      const SampledTrace trace = condition.hand
                                     ? realistic_trace(glyphs, words[i], *condition.hand, root.fork(i).next_u64())
                                     : unsampled(golds[i]);
      starts.push_back(infilled_symbol_starts(trace.trace, trace.symbol_starts));
      demos.push_back({words[i], writing_step_sequence(trace.trace, writing::AlphabetKind::Classic, words[i]),
                       std::vector<int>(starts.back().begin() + 1, starts.back().end())});
    }
    std::vector<StepSequence> steps;
    for (const SkillDemo& d : demos) steps.push_back(d.steps);
    const std::vector<Segmentation> learner = extractor.extract_all(steps);
    WritingRobustnessRow row{condition.name, writing_boundary_score(learner, demos), 0, 0};
    for (std::size_t i = 0; i < words.size(); ++i) {
      for (std::size_t k = 0; k < words[i].size(); ++k) {
        if (writing::is_connector(words[i][k])) continue;
        const int want = majority_skill(expert[i], golds[i].symbol_starts[k],
                                        range_end(golds[i].symbol_starts, k, gold_steps[i].length()));
        const int got = majority_skill(learner[i], starts[i][k], range_end(starts[i], k, steps[i].length()));
        ++row.letters;
        row.agreeing += want == got;
      }
    }
    rows.push_back(row);
  }
  return rows;
}

std::string robustness_table(const std::vector<WritingRobustnessRow>& rows) {
  std::string out = "| condition | boundary F1 (precision / recall) | letter->skill agreement |\n|---|---|---|\n";
  char line[512];
  for (const WritingRobustnessRow& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %.3f (%.3f / %.3f) | %.3f (%d of %d letters) |\n", r.condition.c_str(),
                  r.boundaries.f1(), r.boundaries.precision(), r.boundaries.recall(), r.agreement(), r.agreeing,
                  r.letters);
    out += line;
  }
  return out;
}

}  // namespace sc
