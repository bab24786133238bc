#include "teaching/tasks/skill_training_data.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/step_data.hpp"
#include "engine/writing/word_generator.hpp"
#include "engine/writing/writing_scenario.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/repeat_boundaries.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/writing_other_hand.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {

std::vector<StepSequence> SkillDataSet::steps() const {
  std::vector<StepSequence> out;
  out.reserve(demos.size());
  for (const auto& d : demos) out.push_back(d.steps);
  return out;
}

SkillDataSet generate_parking_demos(int count, std::uint64_t seed) {
  if (count < 1) throw InputError("parking demonstrations", "count must be at least 1");
  const ParkingExpert expert;
  SkillDataSet out{"parking", "", {}, {}, {}};
  for (int i = 0; i < count; ++i) {
    const ParkingScenario scenario = parking_pool_scenario(seed, i);
    const ParkingPlan plan = expert.plan(scenario);
    const ParkingTrial trial = plan.to_trial(scenario);
    // A plan that never parks is not a demonstration of parking skills.
    if (!trial.success.value_or(false)) continue;
    out.demos.push_back({"scenario " + std::to_string(i), parking_step_sequence(trial), {}});
  }
  out.description = std::to_string(out.demos.size()) + " parked ParkingExpert plans out of " + std::to_string(count) +
                    " random classic scenarios (parking_pool_scenario(seed " + std::to_string(seed) + ", 0.." +
                    std::to_string(count - 1) + "))";
  return out;
}

SkillDataSet generate_writing_demos(int count, std::uint64_t seed) {
  if (count < 1) throw InputError("writing demonstrations", "count must be at least 1");
  const std::vector<std::string> words = writing::classic_words(count, seed);
  const writing::GlyphSet glyphs =
      writing::GlyphSet::load(writing::AlphabetKind::Classic, writing::omniglot_data_dir());
  SkillDataSet out{"writing", "", {}, {}, {}};
  for (int i = 0; i < count; ++i) {
    const writing::WordTrajectory gold = writing::build_word_trajectory(glyphs, words[static_cast<std::size_t>(i)]);
    const writing::WritingStepData data = writing::expert_step_data(gold);
    // character_starts[0] is 0: the interior boundaries are the starts of symbols 2..n.
    std::vector<int> boundaries(data.character_starts.begin() + (data.character_starts.empty() ? 0 : 1),
                                data.character_starts.end());
    out.demos.push_back({gold.word, writing_step_sequence(data), std::move(boundaries)});
  }
  out.description = std::to_string(count) +
                    " gold trajectories of classic words from the reference's generator (seed " + std::to_string(seed) +
                    ")";
  return out;
}

namespace {

// Interior boundaries (action indices) of `word`'s points moved to the infilled mouse readings of a sampling:
// entry k of `lists` is a list of point indices; boundaries that would not stay ascending are dropped, and
// kept[k][j] says whether boundary j of list k survived.
std::vector<std::vector<int>> mouse_copy(const WrittenWord& word, std::vector<std::vector<int>> lists, Rng& rng,
                                         StepSequence& steps, std::vector<std::vector<bool>>& kept) {
  std::vector<int> points{0};
  for (const auto& list : lists) points.insert(points.end(), list.begin(), list.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  WrittenWord marked = word;
  marked.symbol_starts = points;
  const SampledTrace sampled = mouse_sampled(marked, MouseSampling{}, rng);
  const std::vector<int> moved = infilled_symbol_starts(sampled.trace, sampled.symbol_starts);
  steps = writing_step_sequence(sampled.trace, writing::AlphabetKind::Classic, word.word);
  kept.assign(lists.size(), {});
  for (std::size_t k = 0; k < lists.size(); ++k) {
    std::vector<int> out;
    for (int p : lists[k]) {
      const auto at = std::lower_bound(points.begin(), points.end(), p) - points.begin();
      const int b = moved[static_cast<std::size_t>(at)];
      kept[k].push_back(b > (out.empty() ? 0 : out.back()) && b < steps.length());
      if (kept[k].back()) out.push_back(b);
    }
    lists[k] = std::move(out);
  }
  return lists;
}

// The units of a copy's segments when some of its boundaries were dropped (kept[j] false): segments joined
// by a dropped boundary are no one unit (-1).
std::vector<int> units_after_drops(const std::vector<int>& units, const std::vector<bool>& kept) {
  std::vector<int> out{units.front()};
  for (std::size_t j = 0; j < kept.size(); ++j) {
    if (kept[j])
      out.push_back(units[j + 1]);
    else
      out.back() = -1;
  }
  return out;
}

// A perturbed copy and the warm start's boundaries and units it inherits.
struct WarmCopy {
  WrittenWord word;
  std::vector<int> boundaries;
  std::vector<int> units;
};

void add_copy(SkillDataSet& out, const std::string& label, const WarmCopy& copy, bool mouse, Rng& rng) {
  const std::string& word = copy.word.word;
  if (!mouse) {
    out.demos.push_back(
        {label, writing_step_sequence(writing::trace_step_data(copy.word.points, writing::AlphabetKind::Classic, word)),
         copy.word.interior_boundaries()});
    out.warm_boundaries.push_back(copy.boundaries);
    out.warm_units.push_back(copy.units);
    return;
  }
  StepSequence steps;
  std::vector<std::vector<bool>> kept;
  auto moved = mouse_copy(copy.word, {copy.word.interior_boundaries(), copy.boundaries}, rng, steps, kept);
  out.demos.push_back({label, std::move(steps), std::move(moved[0])});
  out.warm_boundaries.push_back(std::move(moved[1]));
  out.warm_units.push_back(units_after_drops(copy.units, kept[1]));
}

std::string augmented_description(int count, int copies, std::uint64_t seed, const WritingAugmentation& a) {
  return std::to_string(count) + " classic words of the reference's generator (seed " + std::to_string(seed) +
         "), letters by " +
         (a.drawers == AugmentDrawers::PaperAndTraining ? "the paper's and Omniglot drawers 1-10"
                                                        : "the paper's drawer") +
         ", plus " + std::to_string(copies) + (copies == 1 ? " perturbed copy" : " perturbed copies") +
         " each (wobble <= 12 px, affine <= 0.12" + (a.mouse ? ", mouse-sampled" : "") + ")" +
         (a.other_hands > 0 ? " and " + std::to_string(a.other_hands) + (a.other_hands == 1 ? " copy" : " copies") +
                                  " by drawers 1-10 aligned to them (writing_other_hand.hpp),"
                            : "") +
         " with the clean words' repetition boundaries";
}

}  // namespace

SkillDataSet generate_augmented_writing_demos(int count, int copies, std::uint64_t seed,
                                              const WritingAugmentation& augmentation) {
  if (count < 1 || copies < 0)
    throw InputError("writing demonstrations", "count must be at least 1, copies at least 0");
  const std::vector<std::string> words = writing::classic_words(count, seed);
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  std::vector<int> drawers_pool =
      augmentation.drawers == AugmentDrawers::PaperAndTraining ? training_drawers() : std::vector<int>{};
  drawers_pool.push_back(0);  // the paper's drawer
  const Rng root = Rng(seed).fork(0xa0a0u);
  std::vector<WrittenWord> clean;
  std::vector<StepSequence> clean_steps;
  for (int i = 0; i < count; ++i) {
    Rng rng = root.fork(static_cast<std::uint64_t>(i));
    const std::string& word = words[static_cast<std::size_t>(i)];
    std::vector<int> drawers;
    for (std::size_t k = 0; k < word.size(); ++k) drawers.push_back(drawers_pool[rng.below(drawers_pool.size())]);
    clean.push_back(written_word(glyphs, word, drawers));
    clean_steps.push_back(
        writing_step_sequence(writing::trace_step_data(clean.back().points, writing::AlphabetKind::Classic, word)));
  }
  RepeatBoundaryConfig repeat;
  repeat.max_boundaries = CompileConfig::writing_defaults().num_segments - 1;
  const std::vector<std::vector<int>> warm = find_repeat_boundaries(clean_steps, repeat);
  const std::vector<std::vector<int>> units =
      repeat_units(clean_steps, warm, CompileConfig::writing_defaults().latent_size, repeat.token_precision);
  SkillDataSet out{"writing", augmented_description(count, copies, seed, augmentation), {}, {}, {}};
  const std::vector<int> other_drawers = training_drawers();
  for (int i = 0; i < count; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    out.demos.push_back({words[u], clean_steps[u], clean[u].interior_boundaries()});
    out.warm_boundaries.push_back(warm[u]);
    out.warm_units.push_back(units[u]);
    for (int c = 0; c < copies + augmentation.other_hands; ++c) {
      Rng rng = root.fork(static_cast<std::uint64_t>(i)).fork(1u + static_cast<std::uint64_t>(c));
      const bool other_hand = c >= copies;
      WarmCopy source{clean[u], warm[u], units[u]};
      if (other_hand) {
        std::vector<int> drawers;
        for (std::size_t k = 0; k < words[u].size(); ++k)
          drawers.push_back(other_drawers[rng.below(other_drawers.size())]);
        source.word = written_word(glyphs, words[u], drawers);
        const CarriedBoundaries carried = carried_boundaries(clean[u], source.word, warm[u]);
        source.boundaries = carried.boundaries;
        source.units = units_after_drops(units[u], carried.kept);
      }
      const double wobble = rng.uniform(0.0, 12.0), affine = rng.uniform(0.0, 0.12);
      source.word = perturbed(source.word, {wobble, affine}, rng);
      const std::string label =
          words[u] +
          (other_hand ? " (other hand " + std::to_string(c - copies + 1) : " (copy " + std::to_string(c + 1)) + ")";
      add_copy(out, label, source, augmentation.mouse, rng);
    }
  }
  return out;
}

SkillDataSet generate_task_demos(TaskKind task, int count, std::uint64_t seed) {
  return task == TaskKind::parking ? generate_parking_demos(count, seed) : generate_writing_demos(count, seed);
}

namespace {

StepSequence trial_steps(TaskKind task, const std::filesystem::path& file) {
  const Json doc = read_json_file(file);
  const std::string name = file.string(), task_name(to_string(task));
  if (!doc.is_object() || !doc.contains("task") || doc["task"] != task_name)
    throw InputError(name, "not a " + task_name + " trial ($.task is not \"" + task_name + "\")");
  if (task == TaskKind::parking) return parking_step_sequence(parse_parking_trial(doc, name));
  return writing_step_sequence(writing::parse_writing_trial(doc, name));
}

}  // namespace

SkillDataSet read_task_demos(TaskKind task, const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) throw InputError(dir.string(), "not a folder of trial files");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(dir.string(), "contains no .json trial files");
  SkillDataSet out{
      std::string(to_string(task)),
      std::to_string(files.size()) + " " + std::string(to_string(task)) + " trial files from " + dir.string(),
      {},
      {},
      {}};
  for (const auto& file : files) {
    StepSequence steps = trial_steps(task, file);
    if (steps.length() == 0) throw InputError(file.string(), "trial has no steps");
    out.demos.push_back({file.filename().string(), std::move(steps), {}});
  }
  return out;
}

DataSplit split_demos(const SkillDataSet& data, double valid_fraction, std::uint64_t seed) {
  const std::size_t n = data.demos.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  Rng rng = Rng(seed).fork(0x5b117u);
  for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  std::size_t held = static_cast<std::size_t>(std::lround(valid_fraction * static_cast<double>(n)));
  if (n >= 2)
    held = std::clamp<std::size_t>(held, 1, n - 1);
  else
    held = 0;
  DataSplit out;
  for (std::size_t i = 0; i < n; ++i) {
    const SkillDemo& demo = data.demos[order[i]];
    (i < held ? out.valid : out.train).push_back(demo.steps);
    (i < held ? out.valid_boundaries : out.train_boundaries).push_back(demo.true_boundaries);
    if (i >= held && !data.warm_boundaries.empty()) out.train_warm_boundaries.push_back(data.warm_boundaries[order[i]]);
    if (i >= held && !data.warm_units.empty()) out.train_warm_units.push_back(data.warm_units[order[i]]);
  }
  return out;
}

}  // namespace sc
