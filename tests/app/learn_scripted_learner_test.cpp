// The scripted learner of headless runs and the trainer's goldens: a learner in a hand of its own.
#include "app/core/learn_scripted_learner.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {
namespace {

Json guide(const std::string& word) {
  return writing::writing_trial_json(writing::gold_trial({word, writing::AlphabetKind::Classic, {}}));
}

std::vector<writing::TracePoint> points_of(const Json& trial) {
  return writing::parse_writing_trial(trial, "attempt").points;
}

TEST(ScriptedLearner, HandZeroIsTheGuidesShapes) {
  const Json reference = guide("ba-t");
  EXPECT_EQ(scripted_attempt(reference, 0.6, 7, "mouse", 0), scripted_attempt(reference, 0.6, 7, "mouse"));
}

TEST(ScriptedLearner, AHandWritesTheDrawersLettersFromTheGuidesStart) {
  const Json reference = guide("ba-t");
  const std::vector<writing::TracePoint> attempt = points_of(scripted_attempt(reference, 1.0, 7, "mouse", 4));
  const WrittenWord drawn = written_word(ClassicDrawerGlyphs::load(), "ba-t", {4, 4, 4, 4});
  ASSERT_EQ(attempt.size(), drawn.points.size());
  // At skill 1 the error is zero: the drawer's word, moved so that it starts where the guide does.
  const writing::TracePoint start = points_of(reference).front();
  EXPECT_NEAR(attempt.front().x, start.x, 1e-9);
  EXPECT_NEAR(attempt.front().y, start.y, 1e-9);
  const double dx = start.x - drawn.points.front().x, dy = start.y - drawn.points.front().y;
  for (std::size_t i = 0; i < attempt.size(); ++i) {
    EXPECT_NEAR(attempt[i].x, drawn.points[i].x + dx, 1e-9);
    EXPECT_NEAR(attempt[i].y, drawn.points[i].y + dy, 1e-9);
  }
  const writing::WritingTrial kept = writing::parse_writing_trial(scripted_attempt(reference, 1.0, 7, "mouse", 4), "a");
  EXPECT_EQ(kept.times.size(), kept.points.size());
  EXPECT_NE(points_of(scripted_attempt(reference, 1.0, 7, "mouse", 9)), attempt);
}

TEST(ScriptedLearner, AHandNeedsAClassicWord) {
  const Json balinese =
      writing::writing_trial_json(writing::gold_trial({"B-P", writing::AlphabetKind::Balinese, {{'B', 7}}}));
  EXPECT_THROW(scripted_attempt(balinese, 0.6, 7, "mouse", 4), InputError);
}

}  // namespace
}  // namespace sc
