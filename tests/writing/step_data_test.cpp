#include "engine/writing/step_data.hpp"

#include <gtest/gtest.h>

namespace sc::writing {
namespace {

TEST(StepData, ExpertClassicWordMatchesGetDataSequence) {
  const GlyphSet glyphs = GlyphSet::load(AlphabetKind::Classic, omniglot_data_dir());
  const auto word = build_word_trajectory(glyphs, "-a^");
  const auto data = expert_step_data(word);
  EXPECT_EQ(data.state_dim, 13);
  EXPECT_EQ(data.action_dim, 2);
  ASSERT_EQ(data.length(), 20 + 724 + 40);
  ASSERT_EQ(data.states.size(), static_cast<std::size_t>(data.length()) * 13);
  EXPECT_EQ(data.character_starts, (std::vector<int>{0, 20, 744}));
  // State 0 = [0, 150, timer 0, goal 5 0 6 -1 ...]; action 0 = (+1, 0) of the '-'.
  const std::vector<float> s0(data.states.begin(), data.states.begin() + 13);
  EXPECT_EQ(s0, (std::vector<float>{0, 150, 0, 5, 0, 6, -1, -1, -1, -1, -1, -1, -1}));
  EXPECT_EQ(data.actions[0], 1.0f);
  EXPECT_EQ(data.actions[1], 0.0f);
  // State 20 is where 'a' starts: (20, 150), timer 20; its first action is the lead-in (0, -1).
  EXPECT_EQ(data.states[20 * 13 + 0], 20.0f);
  EXPECT_EQ(data.states[20 * 13 + 1], 150.0f);
  EXPECT_EQ(data.states[20 * 13 + 2], 20.0f);
  EXPECT_EQ(data.actions[20 * 2 + 1], -1.0f);
  // Last action is the '^''s final (+1, +2).
  EXPECT_EQ(data.actions[data.actions.size() - 1], 2.0f);
}

TEST(StepData, BalineseActionsCarryThePen) {
  const GlyphSet glyphs = GlyphSet::load(AlphabetKind::Balinese, omniglot_data_dir());
  const auto word = build_word_trajectory(glyphs, "P-A");
  const auto data = expert_step_data(word);
  EXPECT_EQ(data.action_dim, 3);
  ASSERT_EQ(data.length(), static_cast<int>(word.steps.size()));
  int lifted = 0;
  for (int t = 0; t < data.length(); ++t) {
    const float pen = data.actions[static_cast<std::size_t>(t) * 3 + 2];
    EXPECT_EQ(pen, word.steps[static_cast<std::size_t>(t)].pen ? 1.0f : 0.0f);
    lifted += pen == 0.0f;
  }
  EXPECT_GT(lifted, 0);
  EXPECT_EQ(data.character_starts.size(), 3u);
}

TEST(StepData, LearnerTraceHasNoBoundaries) {
  const std::vector<TracePoint> trace{{10, 150, false}, {11, 150, true}, {11, 149, true}};
  const auto data = trace_step_data(trace, AlphabetKind::Classic, "a");
  EXPECT_EQ(data.length(), 2);
  EXPECT_TRUE(data.character_starts.empty());
  EXPECT_EQ(data.actions, (std::vector<float>{1, 0, 0, -1}));
  EXPECT_EQ(data.states[13 + 2], 1.0f);  // timer of state 1
  EXPECT_EQ(data.states[3], 0.0f);       // goal[0] = 'a'
  EXPECT_EQ(trace_step_data(trace, AlphabetKind::Balinese, "A").actions, (std::vector<float>{1, 0, 1, 0, -1, 1}));
}

}  // namespace
}  // namespace sc::writing
