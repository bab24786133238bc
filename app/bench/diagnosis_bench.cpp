// Benchmarks of the writing pre-test's analysis beyond segmentation (BM_CompileSegmentFiveWriting measures
// that): quality-aware expertise - each expert segment aligned with the learner's trace by time warping and
// scored against the expert and the ten reference hands (docs/skills.md, "The learner's own hand as the
// yardstick") - for a 5-word pre-test, with the time heuristic as extractor so that only the expertise is timed.
#include <benchmark/benchmark.h>

#include <memory>

#include "teaching/sessions/session_analysis.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/writing_hand_references.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_planted_weakness.hpp"

namespace {

const sc::WritingKit& bench_kit() {
  static const sc::WritingKit kit(std::make_shared<sc::TimeHeuristicExtractor>(sc::kWritingTimeSlices), "");
  return kit;
}

// A noise-only learner's trials of the app's pre-test, as the trainer analyses them.
std::vector<sc::TestTrial> pretest_of(int hand_drawer) {
  const sc::WritingKit& kit = bench_kit();
  const std::vector<std::string> words = sc::pretest_words(kit);
  sc::PlantedLearner learner = sc::noise_only_learner(1, 0);
  learner.hand_drawer = hand_drawer;
  const std::vector<sc::Json> docs = sc::planted_pretest_trials(sc::ClassicDrawerGlyphs::load(), words, learner);
  std::vector<sc::TestTrial> out;
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::size_t k = 0; k < kit.gold_words().size(); ++k)
      if (kit.gold_words()[k].word == words[i])
        out.push_back({static_cast<int>(k), kit.expert_pool()[k].skills, docs[i], kit.expert_pool()[k].steps});
  return out;
}

// The kit's hand references are written once per word and kept: after the first iteration this is the cost
// of every later learner's analysis.
void BM_WritingPretestExpertise(benchmark::State& state) {
  const std::vector<sc::TestTrial> trials = pretest_of(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(sc::diagnose_trials(bench_kit(), trials));
}
BENCHMARK(BM_WritingPretestExpertise)->ArgName("hand_drawer")->Arg(0)->Arg(13)->Unit(benchmark::kMillisecond);

// What the first learner's analysis pays once per pre-test word: the drawers' glyphs read, the word written in
// ten hands and aligned with the expert's.
void BM_WritingHandReferencesOneWord(benchmark::State& state) {
  const sc::ExpertDemo& demo = bench_kit().expert_pool().front();
  const std::string word = bench_kit().gold_words().front().word;
  for (auto _ : state) {
    const sc::WritingHandReferences fresh(sc::writing::omniglot_data_dir());
    benchmark::DoNotOptimize(fresh.references(word, demo.steps));
  }
}
BENCHMARK(BM_WritingHandReferencesOneWord)->Unit(benchmark::kMillisecond);

}  // namespace
