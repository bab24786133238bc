// Writing students: the pen's state and rollout, and the planted deficits (cut along the true characters).
#include "teaching/students/writing_students.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "engine/writing/writing_scenario.hpp"
#include "teaching/students/writing_pen_policy.hpp"

namespace sc {
namespace {

std::vector<writing::WordTrajectory> words() {
  std::vector<writing::WordTrajectory> out;
  for (const char* w : {"b-a-t-^-", "c-a-t---", "-e-^a---"})
    out.push_back(writing::gold_trajectory({w, writing::AlphabetKind::Classic, {}}));
  return out;
}

// A pair's state (x, y, timer, goal) is unique over these words: the timer and goal name the word and step.
std::vector<float> state_of(const BcDataset& d, int i) {
  const auto sd = static_cast<std::size_t>(d.state_dim);
  return {d.states.begin() + static_cast<long>(i * sd), d.states.begin() + static_cast<long>((i + 1) * sd)};
}

TEST(WritingStudents, LabelsEveryExpertPairWithItsCharacter) {
  const auto ws = words();
  const LabelledPenPairs p = labelled_pen_pairs(ws);
  std::size_t steps = 0;
  for (const auto& w : ws) steps += w.steps.size();
  ASSERT_EQ(p.pairs.size(), static_cast<int>(steps));
  ASSERT_EQ(p.symbol.size(), steps);
  EXPECT_EQ(p.pairs.state_dim, 13);
  EXPECT_EQ(p.pairs.action_dim, 2);
  // The first word's letters in order, each over exactly its character's steps.
  const auto& w = ws[0];
  for (std::size_t k = 0; k < w.word.size(); ++k) {
    const int begin = w.character_starts[k];
    const int end = k + 1 < w.word.size() ? w.character_starts[k + 1] : static_cast<int>(w.steps.size());
    for (int t = begin; t < end; ++t) ASSERT_EQ(p.symbol[static_cast<std::size_t>(t)], w.word[k]);
  }
}

TEST(WritingStudents, MissingLetterHasNoPairFromThatLettersSegments) {
  const LabelledPenPairs p = labelled_pen_pairs(words());
  for (char letter : std::string("abcte")) {
    WritingStudentRecipe r;
    r.letter = letter;
    const BcDataset d = deficit_pairs(p, r);
    const auto letters = std::count(p.symbol.begin(), p.symbol.end(), letter);
    EXPECT_EQ(d.size(), p.pairs.size() - static_cast<int>(letters)) << letter;
    std::set<std::vector<float>> kept;
    for (int i = 0; i < d.size(); ++i) kept.insert(state_of(d, i));
    for (int i = 0; i < p.pairs.size(); ++i)
      EXPECT_EQ(kept.count(state_of(p.pairs, i)), p.symbol[static_cast<std::size_t>(i)] == letter ? 0u : 1u);
  }
}

TEST(WritingStudents, DistortedLetterIsMirroredAndEverythingElseIsUntouched) {
  const LabelledPenPairs p = labelled_pen_pairs(words());
  WritingStudentRecipe r;
  r.deficit = PenDeficit::DistortedLetter;
  r.letter = 'a';
  const BcDataset d = deficit_pairs(p, r);
  ASSERT_EQ(d.size(), p.pairs.size());
  EXPECT_EQ(d.states, p.pairs.states);
  int mirrored = 0;
  for (std::size_t i = 0; i < p.symbol.size(); ++i) {
    EXPECT_EQ(d.actions[2 * i], p.pairs.actions[2 * i]);
    const float dy = p.pairs.actions[2 * i + 1];
    EXPECT_EQ(d.actions[2 * i + 1], p.symbol[i] == 'a' ? -dy : dy);
    mirrored += p.symbol[i] == 'a' && dy != 0.0f;
  }
  EXPECT_GT(mirrored, 100);
}

TEST(WritingStudents, HalfTrainedSeesEverythingAndBadLettersAreInputErrors) {
  const LabelledPenPairs p = labelled_pen_pairs(words());
  WritingStudentRecipe half;
  half.deficit = PenDeficit::HalfTrained;
  EXPECT_EQ(deficit_pairs(p, half).actions, p.pairs.actions);
  WritingStudentRecipe bad;
  bad.letter = '-';
  EXPECT_THROW(deficit_pairs(p, bad), InputError);
  const auto defaults = WritingStudentRecipe::defaults(30);
  ASSERT_EQ(defaults.size(), 7u);
  EXPECT_EQ(defaults[0].name(), "missing 'a'");
  EXPECT_EQ(defaults[5].key(), "distorted-a");
  EXPECT_EQ(defaults[6].epochs, 3);
}

TEST(WritingPenPolicy, RollsOutFromTheWordsStartForTheExpertsStepsWithTheExpertsStateLayout) {
  const writing::WordTrajectory gold = words()[0];
  const BcPolicy policy(13, 2, 8, 5);
  const auto trace = rollout_pen(policy, gold);
  ASSERT_EQ(trace.size(), gold.steps.size() + 1);
  EXPECT_EQ(trace[0].x, writing::kStartX);
  EXPECT_EQ(trace[0].y, writing::kStartY);
  // Replaying: each step is the policy's action on the scaled state [pen x, pen y, t, goal].
  for (std::size_t t = 0; t < 5; ++t) {
    std::vector<float> raw{static_cast<float>(trace[t].x), static_cast<float>(trace[t].y), static_cast<float>(t)};
    for (int g : gold.goal) raw.push_back(static_cast<float>(g));
    const std::vector<float> a = policy.act(pen_features(raw.data()));
    // (the pen starts on the canvas' left edge, which bounds it)
    EXPECT_NEAR(trace[t + 1].x, std::max(0.0, trace[t].x + kPenActionScale * a[0]), 1e-9);
    EXPECT_NEAR(trace[t + 1].y, trace[t].y + kPenActionScale * a[1], 1e-9);
  }
  // The expert's own state rows scale to the same features the rollout feeds the network.
  const writing::WritingStepData expert = writing::expert_step_data(gold);
  BcDataset raw{13, 2, expert.states, expert.actions};
  const BcDataset units = pen_dataset(raw);
  EXPECT_EQ(std::vector<float>(units.states.begin(), units.states.begin() + 13), pen_features(expert.states.data()));
  EXPECT_FLOAT_EQ(units.actions[0], static_cast<float>(expert.actions[0] / kPenActionScale));
  EXPECT_EQ(pen_trace_reward(gold, gold.points()), 0.0);
  EXPECT_LT(pen_trace_reward(gold, trace), 0.0);
  EXPECT_EQ(rollout_pen(policy, gold), trace);  // deterministic
}

TEST(WritingPenPolicy, RejectsPairsOfAnotherShape) {
  BcDataset parking{12, 2, std::vector<float>(12, 0.0f), {0.0f, 0.0f}};
  EXPECT_THROW(pen_dataset(parking), InputError);
}

}  // namespace
}  // namespace sc
