// CompILE training on data with planted structure: boundaries recovered, skills consistent, loss falls,
// same seed -> same bytes.
#include "teaching/skills/compile_trainer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/repeat_boundaries.hpp"
#include "teaching/skills/segmentation_metrics.hpp"
#include "teaching/skills/synthetic_sequences.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

std::filesystem::path scratch(const std::string& name) { return test::scratch_path("compile_trainer_test", name); }

std::vector<StepSequence> steps_of(const std::vector<PlantedSequence>& planted) {
  std::vector<StepSequence> out;
  for (const auto& p : planted) out.push_back(p.steps);
  return out;
}

CompileConfig tiny_config() {
  CompileConfig c;
  c.task = "synthetic";
  c.mode = CompileMode::Action;
  c.latent_size = 6;
  c.num_segments = 3;
  c.hidden = 32;
  c.prior_rate = 8.0;
  c.learning_rate = 5e-3;
  c.batch_size = 40;
  c.iterations = 150;
  c.eval_interval = 5;
  c.patience = 100;
  c.seed = 7;
  return c;
}

TEST(CompileTrainer, RecoversPlantedBoundariesAndConsistentSkills) {
  // 3 constant-action primitives of random lengths 5..12, three per sequence.
  const auto train = constant_primitive_sequences(120, 3, 3, 5, 12, 0, 11);
  const auto valid = constant_primitive_sequences(20, 3, 3, 5, 12, 0, 12);
  const auto test = constant_primitive_sequences(60, 3, 3, 5, 12, 0, 13);
  CompileConfig config = tiny_config();
  config.iterations = 400;
  config.restarts = 4;
  config.seed = 0;
  CompileTrainer trainer(config);
  std::vector<double> losses;  // of the run that was kept
  std::vector<std::vector<double>> run_losses(static_cast<std::size_t>(config.restarts));
  const CompileModel model = trainer.train(steps_of(train), steps_of(valid), [&](const TrainingProgress& p) {
    run_losses[static_cast<std::size_t>(p.restart)].push_back(p.loss);
  });
  losses = run_losses[static_cast<std::size_t>(trainer.summary().restart)];
  ASSERT_GE(losses.size(), 20u);
  EXPECT_LT(losses.back(), 0.7 * losses.front()) << "first " << losses.front() << " last " << losses.back();
  EXPECT_GT(trainer.summary().best_iteration, 0);

  const auto segs = model.segment(steps_of(test));
  BoundaryScore score;
  std::map<int, std::map<int, int>> skill_votes;  // primitive -> skill -> steps
  for (std::size_t i = 0; i < test.size(); ++i) {
    std::vector<int> truth(test[i].boundaries.begin(), test[i].boundaries.end() - 1);
    score += score_boundaries(interior_boundaries(segs[i]), truth, 1);
    int seg_begin = 0;
    for (std::size_t s = 0; s < test[i].boundaries.size(); ++s) {
      for (const auto& ps : segs[i].segments)
        for (int t = std::max(ps.begin, seg_begin); t < std::min(ps.end, test[i].boundaries[s]); ++t)
          ++skill_votes[test[i].primitives[s]][ps.skill];
      seg_begin = test[i].boundaries[s];
    }
  }
  // Share of steps whose skill is the majority skill of their primitive.
  int majority = 0, total = 0;
  for (const auto& [prim, votes] : skill_votes) {
    int best = 0;
    for (const auto& [skill, n] : votes) {
      best = std::max(best, n);
      total += n;
    }
    majority += best;
  }
  const double consistency = static_cast<double>(majority) / total;
  std::printf("boundary F1 %.3f (P %.3f R %.3f), skill consistency %.3f, %d iterations in %.1f s\n", score.f1(),
              score.precision(), score.recall(), consistency, trainer.summary().iterations_run,
              trainer.summary().seconds);
  // One run's F1 depends on the seed and on float rounding (BLAS kernels, our LSTM kernels): over seeds
  // 0..15 a single 150-iteration run reached 0.57..1.00, and a best-of-3 at seeds 7..9 passed with one
  // build and failed with another (gradients equal to 1e-7). At 400 iterations single runs of seeds 0..7
  // reached F1 0.75..0.97 (one build) and 0.65..1.00 (the other), and the validation NLL mostly picks a
  // good one, so the test keeps the best of 4; with 60 iterations F1 was only ~0.5, so these bounds do
  // fail for an undertrained or broken model. Skill consistency moves with the machine too: >= 0.85 on the
  // AVX-512 machines of earlier sessions, 0.772 (F1 0.970) on an AMD EPYC without AVX-512 (2026-12-03), where
  // one primitive is shared between two latent codes; a model that assigns skills at random scores ~0.4.
  EXPECT_GE(score.f1(), 0.7);
  EXPECT_GE(consistency, 0.7);
}

TEST(CompileTrainer, RestartsKeepTheRunWithTheLowestValidationNll) {
  const auto data = steps_of(constant_primitive_sequences(20, 3, 3, 4, 8, 0, 5));
  const auto valid = steps_of(constant_primitive_sequences(8, 3, 3, 4, 8, 0, 6));
  CompileConfig c = tiny_config();
  c.iterations = 4;
  c.eval_interval = 2;
  c.batch_size = 8;
  c.restarts = 3;
  CompileTrainer trainer(c);
  trainer.train(data, valid).save(scratch("restarts.scm"));
  const TrainingSummary& s = trainer.summary();
  ASSERT_EQ(s.restart_valid_nll.size(), 3u);
  for (double v : s.restart_valid_nll) EXPECT_GE(v, s.best_valid_nll);
  EXPECT_EQ(s.best_valid_nll, s.restart_valid_nll[static_cast<std::size_t>(s.restart)]);
  // The kept run is exactly the single run from its seed (runs share nothing, so threads do not matter).
  CompileConfig single = c;
  single.restarts = 1;
  single.seed = c.seed + static_cast<std::uint64_t>(s.restart);
  CompileTrainer(single).train(data, valid).save(scratch("single.scm"));
  CompileModel a = CompileModel::load(scratch("restarts.scm"));
  CompileModel b = CompileModel::load(scratch("single.scm"));
  EXPECT_EQ(a.segment(data).size(), data.size());
  EXPECT_EQ(a.config().seed, c.seed);  // the configured seed (the data's), whichever run was kept
  const auto sa = a.segment(data), sb = b.segment(data);
  for (std::size_t i = 0; i < data.size(); ++i) EXPECT_EQ(interior_boundaries(sa[i]), interior_boundaries(sb[i])) << i;
}

// The review sees every restart's model, in order, and its score decides: the first, then the last run kept
// (no unit term, so every run is a candidate), whichever the validation NLL prefers.
TEST(CompileTrainer, AReviewScoresEveryRestartAndTheHighestScoreIsKept) {
  const auto data = steps_of(constant_primitive_sequences(20, 3, 3, 4, 8, 0, 5));
  const auto valid = steps_of(constant_primitive_sequences(8, 3, 3, 4, 8, 0, 6));
  CompileConfig c = tiny_config();
  c.iterations = 2;
  c.eval_interval = 2;
  c.batch_size = 8;
  c.restarts = 3;
  for (const double sign : {-1.0, 1.0}) {
    std::vector<int> reviewed;
    CompileTrainer trainer(c);
    trainer.review_restarts_with([&](const CompileModel& model, int restart) {
      reviewed.push_back(restart);
      EXPECT_EQ(model.segment(valid).size(), valid.size());
      return sign * restart;
    });
    trainer.train(data, valid);
    EXPECT_EQ(reviewed, (std::vector<int>{0, 1, 2}));
    const TrainingSummary& s = trainer.summary();
    EXPECT_EQ(s.restart, sign > 0 ? 2 : 0);
    EXPECT_EQ(s.restart_score, (std::vector<double>{0.0 * sign, 1.0 * sign, 2.0 * sign}));
    EXPECT_EQ(s.best_valid_nll, s.restart_valid_nll[static_cast<std::size_t>(s.restart)]);
    EXPECT_TRUE(s.to_json().contains("restart_score"));
  }
  CompileTrainer unreviewed(c);
  unreviewed.train(data, valid);
  EXPECT_FALSE(unreviewed.summary().to_json().contains("restart_score"));
}

TEST(CompileTrainer, SameSeedGivesSameModelBytes) {
  const auto data = steps_of(constant_primitive_sequences(20, 3, 3, 4, 8, 0, 5));
  CompileConfig c = tiny_config();
  c.iterations = 3;
  c.batch_size = 8;
  auto run = [&](std::uint64_t seed, const std::string& name) {
    c.seed = seed;
    CompileTrainer(c).train(data, data).save(scratch(name));
    return test::read_bytes(scratch(name));
  };
  const std::string a = run(1, "a.scm"), b = run(1, "b.scm"), other = run(2, "c.scm");
  ASSERT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, other);
}

// Interior boundaries of planted sequences, each moved by `shift` steps (kept ascending and inside).
std::vector<std::vector<int>> interior_of(const std::vector<PlantedSequence>& planted, int shift) {
  std::vector<std::vector<int>> out;
  for (const auto& p : planted) {
    std::vector<int> inner(p.boundaries.begin(), p.boundaries.end() - 1);
    for (int& b : inner) b += shift;
    out.push_back(inner);
  }
  return out;
}

TEST(CompileTrainer, FixedBoundariesAtThePlantedEdgesReachALowerNllThanShiftedOnes) {
  // The diagnostic of fix_boundaries: with the true segmentation each segment is one constant primitive,
  // which one latent reconstructs exactly; moved by 2 steps, every segment but the first mixes two
  // primitives. Measured: 0.03 at the truth vs 16.1 shifted at 150 iterations (at 60 iterations the truth
  // was still at 9.0: undertrained), so a factor of 4 leaves room and still fails if fixing did nothing.
  const auto train = constant_primitive_sequences(60, 3, 3, 5, 12, 0, 21);
  const auto valid = constant_primitive_sequences(20, 3, 3, 5, 12, 0, 22);
  CompileConfig c = tiny_config();
  c.iterations = 150;
  auto valid_nll = [&](int shift) {
    CompileTrainer trainer(c);
    trainer.fix_boundaries(interior_of(train, shift), interior_of(valid, shift));
    trainer.train(steps_of(train), steps_of(valid));
    return trainer.summary().best_valid_nll;
  };
  const double at_truth = valid_nll(0), shifted = valid_nll(2);
  std::printf("validation NLL with boundaries fixed at the truth %.3f, shifted by 2 steps %.3f\n", at_truth, shifted);
  EXPECT_LT(4.0 * at_truth, shifted);
}

TEST(CompileTrainer, WarmStartFromRepeatBoundariesSegmentsNewWordsAtTheSymbolEdges) {
  // Symbols that repeat exactly: find_repeat_boundaries finds their edges in the training words, the warm
  // start teaches the network those segments, and free training goes on from there. Measured (seed 0):
  // F1 1.000 on new words; without the warm start the same config reached 0.414.
  const auto train = repeated_symbol_sequences(120, 3, 5, 6, 12, 1, 31);
  const auto valid = repeated_symbol_sequences(20, 3, 5, 6, 12, 1, 32);
  const auto test = repeated_symbol_sequences(60, 3, 5, 6, 12, 1, 33);
  auto f1_of = [&](int warm) {
    CompileConfig c = tiny_config();
    c.seed = 0;
    c.iterations = 40;
    c.warm_start_iterations = warm;
    CompileTrainer trainer(c);
    std::vector<int> warm_reports;
    const CompileModel model = trainer.train(steps_of(train), steps_of(valid), [&](const TrainingProgress& p) {
      if (p.warm_start) warm_reports.push_back(p.iteration);
    });
    EXPECT_EQ(static_cast<int>(warm_reports.size()), warm);
    if (warm > 0) {
      EXPECT_NEAR(trainer.summary().warm_start_boundaries, 2.0, 0.1);
    }
    const auto segs = model.segment(steps_of(test));
    BoundaryScore score;
    for (std::size_t i = 0; i < test.size(); ++i)
      score += score_boundaries(interior_boundaries(segs[i]),
                                std::vector<int>(test[i].boundaries.begin(), test[i].boundaries.end() - 1), 1);
    return score.f1();
  };
  const double warm = f1_of(80), cold = f1_of(0);
  std::printf("boundary F1 on new words: warm start %.3f, without %.3f\n", warm, cold);
  EXPECT_GE(warm, 0.9);
}

TEST(CompileTrainer, WarmStartUnitsGiveEachRepeatedSymbolTheSkillOfItsUnit) {
  // 5 symbols, 3 per word: repeat_units numbers them by frequency and the warm start's unit term pulls
  // unit u's segments to skill u. Without the term the skills are whatever reconstruction settled on.
  const auto train = repeated_symbol_sequences(120, 3, 5, 6, 12, 1, 31);
  const auto valid = repeated_symbol_sequences(20, 3, 5, 6, 12, 1, 32);
  const auto train_steps = steps_of(train);
  const auto units = repeat_units(train_steps, find_repeat_boundaries(train_steps), 6);
  auto share_on_unit_skill = [&](bool with_units) {
    CompileConfig c = tiny_config();
    c.seed = 0;
    c.iterations = 1;
    c.warm_start_iterations = 60;
    c.warm_start_units = with_units;
    CompileTrainer trainer(c);
    double last_unit_ce = -1.0;
    const CompileModel model = trainer.train(train_steps, steps_of(valid), [&](const TrainingProgress& p) {
      if (p.warm_start) last_unit_ce = p.unit_ce;
    });
    EXPECT_EQ(last_unit_ce > 0.0, with_units);
    // The summary keeps the last pass's unit term for choose_restart (NaN without units).
    if (with_units)
      EXPECT_EQ(trainer.summary().warm_start_unit_term, last_unit_ce);
    else
      EXPECT_TRUE(std::isnan(trainer.summary().warm_start_unit_term));
    EXPECT_EQ(trainer.summary().restart_unit_term.size(), 1u);
    const auto segs = model.segment(train_steps);
    int same = 0, labelled = 0;
    for (std::size_t i = 0; i < train.size(); ++i) {
      int begin = 0;
      for (std::size_t j = 0; j < train[i].boundaries.size(); ++j) {
        const int end = train[i].boundaries[j], middle = (begin + end) / 2;
        begin = end;
        if (j >= units[i].size() || units[i][j] < 0) continue;
        ++labelled;
        for (const auto& seg : segs[i].segments)
          if (seg.begin <= middle && middle < seg.end) same += seg.skill == units[i][j];
      }
    }
    return static_cast<double>(same) / std::max(1, labelled);
  };
  const double with = share_on_unit_skill(true), without = share_on_unit_skill(false);
  std::printf("segments on their unit's skill: with the unit term %.3f, without %.3f\n", with, without);
  EXPECT_GE(with, 0.9);
  EXPECT_LT(without, 0.6);
}

TEST(CompileTrainer, FixedBoundariesThatDoNotFitTheDataAreInputErrors) {
  const auto train = constant_primitive_sequences(4, 3, 3, 5, 12, 0, 21);
  CompileConfig c = tiny_config();
  c.iterations = 1;
  auto error_of = [&](std::vector<std::vector<int>> boundaries) {
    CompileTrainer trainer(c);
    trainer.fix_boundaries(std::move(boundaries), {});
    try {
      trainer.train(steps_of(train), {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto good = interior_of(train, 0);
  EXPECT_NE(error_of({good[0]}).find("1 boundary lists for 4 trajectories"), std::string::npos) << error_of({good[0]});
  auto too_many = good;
  too_many[1].push_back(too_many[1].back() + 1);
  EXPECT_NE(error_of(too_many).find("training trajectory 1: 3 boundaries, the model has only 2"), std::string::npos)
      << error_of(too_many);
  auto descending = good;
  std::swap(descending[2][0], descending[2][1]);
  EXPECT_NE(error_of(descending).find("is not ascending"), std::string::npos) << error_of(descending);
  auto outside = good;
  outside[3][1] = train[3].steps.length();
  EXPECT_NE(error_of(outside).find("is not ascending inside 1.."), std::string::npos) << error_of(outside);
  EXPECT_EQ(error_of(good), "no error");
}

// Resident memory in MB (Linux /proc), the measure the leak showed up in.
double resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
    if (key == "VmRSS:") {
      double kb = 0.0;
      status >> kb;
      return kb / 1024.0;
    }
  return 0.0;
}

TEST(CompileTrainer, MemoryDoesNotGrowWithIterations) {
  // The packed LSTM once kept its own output in its autograd context: a reference cycle that leaked every
  // iteration's whole graph (5.7 GB after 400 parking iterations). Measured on this config: with the cycle
  // 1370 MB of growth between iterations 20 and 120 (~14 MB per iteration); without it under 2 MB.
  const auto data = steps_of(constant_primitive_sequences(60, 3, 3, 5, 12, 0, 11));
  CompileConfig c = tiny_config();
  c.iterations = 60;
  double at_10 = 0.0, at_end = 0.0;
  CompileTrainer(c).train(data, {}, [&](const TrainingProgress& p) {
    if (p.iteration == 10) at_10 = resident_mb();
    at_end = resident_mb();
  });
  std::printf("resident memory %.1f MB at iteration 10, %.1f MB at 60\n", at_10, at_end);
  ASSERT_GT(at_10, 0.0);
  EXPECT_LT(at_end - at_10, 20.0);
}

}  // namespace
}  // namespace sc
