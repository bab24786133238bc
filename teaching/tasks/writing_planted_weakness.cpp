#include "teaching/tasks/writing_planted_weakness.hpp"

#include <algorithm>
#include <cstdio>

#include "teaching/curricula/teachable_skills.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/sessions/session_settings.hpp"
#include "teaching/tasks/diagnosis.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/writing_execution.hpp"

namespace sc {
namespace {

constexpr std::string_view kLetters = "abcte";
constexpr LetterFault kFaults[] = {LetterFault::Distorted, LetterFault::OtherDrawer, LetterFault::StraightLine};

// The learner's way of getting its letter wrong, the same in every word it writes.
struct FaultShape {
  int drawer = 0;                     // OtherDrawer
  double scale_y = 1.0, shear = 0.0;  // Distorted
  double wobble_px = 0.0;             // the background hand
};

FaultShape fault_shape(const PlantedLearner& learner) {
  Rng rng = Rng(learner.seed).fork(99);
  FaultShape f;
  f.wobble_px = rng.uniform(2.0, 6.0);
  if (learner.letter != 0) {
    const int own = learner.hand_drawer != 0 ? learner.hand_drawer
                                             : writing::default_drawer(writing::AlphabetKind::Classic, learner.letter);
    f.drawer = 1 + static_cast<int>(rng.below(writing::kDrawersPerCharacter - 1));
    if (f.drawer >= own) ++f.drawer;
  }
  f.scale_y = rng.uniform() < 0.5 ? rng.uniform(0.4, 0.6) : rng.uniform(1.6, 2.0);
  f.shear = (rng.uniform() < 0.5 ? -1.0 : 1.0) * rng.uniform(0.5, 0.8);
  return f;
}

std::pair<std::size_t, std::size_t> symbol_range(const WrittenWord& w, std::size_t k) {
  const std::size_t end =
      k + 1 < w.symbol_starts.size() ? static_cast<std::size_t>(w.symbol_starts[k + 1]) : w.points.size() - 1;
  return {static_cast<std::size_t>(w.symbol_starts[k]), end};
}

// Symbol k's steps through (x, y) -> (x + shear y, scale_y y); the rest of the word follows on.
void distort(WrittenWord& w, std::size_t k, double scale_y, double shear) {
  const auto [a, b] = symbol_range(w, k);
  std::vector<writing::TracePoint> old = w.points;
  for (std::size_t i = a; i + 1 < old.size(); ++i) {
    double dx = old[i + 1].x - old[i].x, dy = old[i + 1].y - old[i].y;
    if (i < b) dx += shear * dy, dy *= scale_y;
    w.points[i + 1] = {w.points[i].x + dx, w.points[i].y + dy, old[i + 1].pen};
  }
}

void straighten(WrittenWord& w, std::size_t k) {
  const auto [a, b] = symbol_range(w, k);
  const writing::TracePoint p0 = w.points[a], p1 = w.points[b];
  for (std::size_t i = a + 1; i < b; ++i) {
    const double f = static_cast<double>(i - a) / static_cast<double>(b - a);
    w.points[i].x = p0.x + f * (p1.x - p0.x);
    w.points[i].y = p0.y + f * (p1.y - p0.y);
  }
}

int letter_skill(const WritingKit& kit, char letter) {
  int best = -1, most = 0;
  const auto& places = kit.skill_places();
  for (std::size_t m = 0; m < places.size(); ++m) {
    const auto it = places[m].character_steps.find(letter);
    if (it != places[m].character_steps.end() && it->second > most) best = static_cast<int>(m), most = it->second;
  }
  return best;
}

ExpertiseEstimate diagnose(const WritingKit& kit, const ClassicDrawerGlyphs& glyphs,
                           const std::vector<std::string>& words, const PlantedLearner& learner, ExpertiseMode mode) {
  return diagnose_trials(kit, planted_pretest_trials(glyphs, words, learner), learner.seed, mode).expertise;
}

// Clean points of `letter` in `drawer`'s shape as a sequence the execution score reads (x, y states).
StepSequence letter_points(const ClassicDrawerGlyphs& glyphs, char letter, int drawer) {
  const WrittenWord w = written_word(glyphs, std::string(1, letter), {drawer});
  StepSequence out;
  out.state_dim = 2;
  out.action_dim = 2;
  for (const writing::TracePoint& p : w.points) {
    out.states.insert(out.states.end(), {static_cast<float>(p.x), static_cast<float>(p.y)});
    out.actions.insert(out.actions.end(), {0.0f, 0.0f});
  }
  return out;
}

// The other-drawer learners split by how far their letter's shape is from the expert's, then each pair.
std::string other_drawer_lines(const PlantedWeaknessReport& report) {
  if (report.other_drawers.empty()) return {};
  const double cut = report.noise_floor ? report.noise_floor->segment : 0.0;
  int n[2] = {0, 0}, found[2] = {0, 0}, pairs[2] = {0, 0};
  for (const auto& [key, cell] : report.other_drawers) {
    const int within = cell.shape_score > cut ? 1 : 0;
    n[within] += cell.learners, found[within] += cell.found, ++pairs[within];
  }
  char line[256];
  std::snprintf(line, sizeof line,
                "other drawer's shape, by its clean shape score against the expert's letter (cut %.3f, %s): "
                "worse %d of %d found (%d letter-drawer pairs), within %d of %d (%d pairs)\n",
                cut, report.noise_floor ? "the noise floor" : "no noise floor recorded", found[0], n[0], pairs[0],
                found[1], n[1], pairs[1]);
  std::string out = line;
  out += "  letter, drawer (shape score): found / learners:";
  for (const auto& [key, cell] : report.other_drawers) {
    std::snprintf(line, sizeof line, " %c%d (%.2f): %d / %d", key.first, key.second, cell.shape_score, cell.found,
                  cell.learners);
    out += line;
  }
  return out + "\n";
}

}  // namespace

std::string to_string(LetterFault fault) {
  switch (fault) {
    case LetterFault::None:
      return "none";
    case LetterFault::Distorted:
      return "distorted";
    case LetterFault::OtherDrawer:
      return "other drawer";
    case LetterFault::StraightLine:
      return "straight line";
  }
  return "?";
}

double other_drawer_shape_score(const ClassicDrawerGlyphs& glyphs, char letter, int drawer) {
  const StepSequence expert = letter_points(glyphs, letter, 0), other = letter_points(glyphs, letter, drawer);
  const StepAlignment path = align_traces(writing_trace_points(expert), writing_trace_points(other));
  return writing_execution_reward(expert, other, path, 0, expert.length());
}

writing::WritingTrial planted_trial(const ClassicDrawerGlyphs& glyphs, const std::string& word,
                                    const PlantedLearner& learner, int word_index) {
  const FaultShape shape = fault_shape(learner);
  std::vector<int> drawers(word.size(), learner.hand_drawer);
  for (std::size_t k = 0; k < word.size(); ++k)
    if (word[k] == learner.letter && learner.fault == LetterFault::OtherDrawer) drawers[k] = shape.drawer;
  WrittenWord w = written_word(glyphs, word, drawers);
  for (std::size_t k = 0; k < word.size(); ++k) {
    if (word[k] != learner.letter) continue;
    if (learner.fault == LetterFault::Distorted) distort(w, k, shape.scale_y, shape.shear);
    if (learner.fault == LetterFault::StraightLine) straighten(w, k);
  }
  const Rng root = Rng(learner.seed).fork(static_cast<std::uint64_t>(word_index));
  Rng noise = root.fork(1), mouse = root.fork(2);
  const SampledTrace trace = mouse_sampled(perturbed(w, {shape.wobble_px, 0.08}, noise), MouseSampling{}, mouse);
  writing::WritingTrial trial;
  trial.scenario = {word, writing::AlphabetKind::Classic, {}};
  trial.points = trace.trace.points;
  trial.times = trace.trace.times;
  trial.source = "learner";
  trial.device = "mouse";
  return trial;
}

std::vector<Json> planted_pretest_trials(const ClassicDrawerGlyphs& glyphs, const std::vector<std::string>& words,
                                         const PlantedLearner& learner) {
  std::vector<Json> trials;
  for (std::size_t i = 0; i < words.size(); ++i)
    trials.push_back(writing::writing_trial_json(planted_trial(glyphs, words[i], learner, static_cast<int>(i))));
  return trials;
}

std::vector<std::string> pretest_words(const WritingKit& kit) {
  std::vector<std::string> words;
  for (int i : select_diverse_scenarios(demo_skills(kit.expert_pool()), SessionSettings{}.pretest_count).scenarios())
    words.push_back(kit.gold_words()[static_cast<std::size_t>(i)].word);
  return words;
}

PlantedLearner noise_only_learner(std::uint64_t seed, int index) {
  return {0, LetterFault::None, Rng(seed).fork(7u + static_cast<std::uint64_t>(index)).next_u64()};
}

int own_hand_drawer(const PlantedLearner& learner) {
  const std::vector<int> unseen = unseen_drawers();
  return unseen[Rng(learner.seed).fork(98).below(unseen.size())];
}

PlantedWeaknessReport measure_planted_weaknesses(const WritingKit& kit, const ClassicDrawerGlyphs& glyphs,
                                                 int learners_per_letter, std::uint64_t seed, ExpertiseMode mode,
                                                 bool own_hands) {
  PlantedWeaknessReport report;
  report.own_hands = own_hands;
  report.noise_floor = kit.execution_noise_floor();
  auto with_hand = [own_hands](PlantedLearner learner) {
    if (own_hands) learner.hand_drawer = own_hand_drawer(learner);
    return learner;
  };
  report.pretest_words = pretest_words(kit);
  const Rng root(seed);
  for (char letter : kLetters) {
    PlantedLetterRow row{letter, letter_skill(kit, letter), 0, 0, std::vector<int>(3, 0), std::vector<int>(3, 0)};
    for (int i = 0; i < learners_per_letter; ++i) {
      const PlantedLearner learner =
          with_hand({letter, kFaults[i % 3], root.fork(1000u * static_cast<unsigned char>(letter) + i).next_u64()});
      const ExpertiseEstimate e = diagnose(kit, glyphs, report.pretest_words, learner, mode);
      const bool hit = !e.targets.empty() && e.targets.front() == row.skill;
      ++row.learners;
      row.top_target += hit;
      ++row.by_fault_learners[static_cast<std::size_t>(i % 3)];
      row.by_fault_top[static_cast<std::size_t>(i % 3)] += hit;
      if (learner.fault == LetterFault::OtherDrawer) {
        const int drawer = fault_shape(learner).drawer;
        OtherDrawerCell& cell = report.other_drawers[{letter, drawer}];
        if (cell.learners++ == 0) cell.shape_score = other_drawer_shape_score(glyphs, letter, drawer);
        cell.found += hit;
      }
    }
    report.letters.push_back(row);
  }
  const std::vector<Segmentation> pool = demo_skills(kit.expert_pool());
  const int min_steps = kit.curriculum_config().min_skill_steps;
  for (int i = 0; i < learners_per_letter; ++i) {
    const ExpertiseEstimate e =
        diagnose(kit, glyphs, report.pretest_words, with_hand(noise_only_learner(seed, i)), mode);
    double lowest = 0.0, lowest_drilled = 0.0;
    for (int m : e.targets) lowest = std::min(lowest, e.expertise[static_cast<std::size_t>(m)]);
    std::vector<int> drilled = teachable_ranking(e, pool, min_steps);
    drilled.resize(std::min(drilled.size(), e.targets.size()));
    for (int m : drilled) lowest_drilled = std::min(lowest_drilled, e.expertise[static_cast<std::size_t>(m)]);
    ++report.noise_learners;
    report.noise_without_confident_target += lowest >= kConfidentTargetExpertise;
    report.noise_without_confident_drill_target += lowest_drilled >= kConfidentTargetExpertise;
    report.noise_lowest_expertise.push_back(lowest);
    if (!e.targets.empty()) ++report.noise_top_targets[e.targets.front()];
  }
  return report;
}

std::string planted_weakness_table(const PlantedWeaknessReport& report) {
  std::string out =
      report.own_hands ? "every learner's letters in its own hand (one of the unseen drawers 11-15)\n" : std::string();
  out += "pre-test words:";
  for (const std::string& w : report.pretest_words) out += " " + w;
  out +=
      "\n\n| letter | its skill | top target is its skill | distorted | other drawer | straight line "
      "|\n|---|---|---|---|---|---|\n";
  char line[512];
  for (const PlantedLetterRow& r : report.letters) {
    std::snprintf(line, sizeof line, "| %c | %d | %d of %d (%.0f %%) | %d / %d | %d / %d | %d / %d |\n", r.letter,
                  r.skill, r.top_target, r.learners, r.learners ? 100.0 * r.top_target / r.learners : 0.0,
                  r.by_fault_top[0], r.by_fault_learners[0], r.by_fault_top[1], r.by_fault_learners[1],
                  r.by_fault_top[2], r.by_fault_learners[2]);
    out += line;
  }
  std::vector<double> lowest = report.noise_lowest_expertise;
  std::sort(lowest.begin(), lowest.end());
  std::snprintf(line, sizeof line,
                "\nnoise-only learners without a target below E = %.2f: %d of %d (%.0f %%); their weakest target's E: "
                "min %.3f, median %.3f\n",
                kConfidentTargetExpertise, report.noise_without_confident_target, report.noise_learners,
                report.noise_learners ? 100.0 * report.noise_without_confident_target / report.noise_learners : 0.0,
                lowest.empty() ? 0.0 : lowest.front(), lowest.empty() ? 0.0 : lowest[lowest.size() / 2]);
  out += line;
  std::snprintf(line, sizeof line,
                "noise-only learners without a drill target below E = %.2f (only skills long enough to drill "
                "alone, as the trainer drills): %d of %d\n",
                kConfidentTargetExpertise, report.noise_without_confident_drill_target, report.noise_learners);
  out += line;
  out += other_drawer_lines(report);
  out += "noise-only learners' first target (skill: learners):";
  for (const auto& [skill, n] : report.noise_top_targets) {
    std::snprintf(line, sizeof line, " %d: %d", skill, n);
    out += line;
  }
  return out + "\n";
}

}  // namespace sc
