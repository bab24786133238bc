#include "engine/writing/writing_score.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "engine/core/rng.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::writing {
namespace {

std::vector<TracePoint> gold_points(const std::string& word, AlphabetKind kind = AlphabetKind::Classic) {
  return gold_trajectory({word, kind, {}}).points();
}

// The gold path as a mouse would report it: the pen moves along it at `speed` px/s and is sampled at `hz`.
std::vector<TracePoint> sampled_along(const std::vector<TracePoint>& path, double speed, double hz) {
  std::vector<TracePoint> out{path.front()};
  const double step = speed / hz;
  double next = step, walked = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double len = std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    while (next <= walked + len) {
      const double f = (next - walked) / len;
      out.push_back(
          {path[i - 1].x + f * (path[i].x - path[i - 1].x), path[i - 1].y + f * (path[i].y - path[i - 1].y), true});
      next += step;
    }
    walked += len;
  }
  out.push_back(path.back());
  return out;
}

void report(const char* what, const WritingScore& s) {
  std::printf("[score] %-28s score %+.4f recall %.4f precision %.4f\n", what, s.score, s.recall, s.precision);
}

TEST(WritingScore, GoldScoresZero) {
  const auto gold = gold_points("b-a-t-^-");
  const auto s = score_writing(gold, gold);
  report("gold", s);
  EXPECT_EQ(s.score, 0.0);
  EXPECT_EQ(s.recall, 1.0);
  EXPECT_EQ(s.precision, 1.0);
  EXPECT_GT(s.gold_ink_px, 1000.0);
  EXPECT_DOUBLE_EQ(s.gold_ink_px, s.learner_ink_px);
}

TEST(WritingScore, SmallWobbleInsideTheToleranceBandStillScoresZero) {
  const auto gold = gold_points("ab-c");
  auto wobbly = sampled_along(gold, 200, 60);
  Rng rng(4);
  for (auto& p : wobbly) p.x += rng.uniform(-1.5, 1.5), p.y += rng.uniform(-1.5, 1.5);
  const auto s = score_writing(gold, wobbly);
  report("wobble +-1.5 px", s);
  EXPECT_GT(s.score, -0.01);
}

TEST(WritingScore, ShiftedByTwentyPixelsScoresMuchLower) {
  const auto gold = gold_points("b-a-t-^-");
  for (auto [dx, dy] : {std::pair{0.0, 20.0}, std::pair{20.0, 0.0}, std::pair{14.1, 14.1}}) {
    auto shifted = gold;
    for (auto& p : shifted) p.x += dx, p.y += dy;
    const auto s = score_writing(gold, shifted);
    report("shifted 20 px", s);
    EXPECT_LT(s.score, -0.7);
    EXPECT_NEAR(s.recall, s.precision, 0.02);  // same ink, same offset: symmetric
  }
  // A 5 px shift is in the tolerance ramp: partial credit.
  auto near = gold;
  for (auto& p : near) p.y += 5;
  const auto s5 = score_writing(gold, near);
  report("shifted 5 px", s5);
  EXPECT_LT(s5.score, -0.1);
  EXPECT_GT(s5.score, -0.7);
}

TEST(WritingScore, HalfAWordScoresAboutHalf) {
  const auto gold = gold_points("b-a-t-^-");
  for (double fraction : {0.25, 0.5, 0.75}) {
    const std::vector<TracePoint> part(gold.begin(),
                                       gold.begin() + static_cast<std::ptrdiff_t>(fraction * gold.size()));
    const auto s = score_writing(gold, part);
    report(("first " + std::to_string(fraction)).c_str(), s);
    EXPECT_NEAR(s.precision, 1.0, 1e-12);
    EXPECT_NEAR(s.score, -(1.0 - fraction), 0.08);
  }
}

TEST(WritingScore, RandomScribblesScoreNearMinusOne) {
  const auto gold = gold_points("b-a-t-^-");
  Rng rng(9);
  // Zig-zags between random canvas points: 40 of them make ~8000 px of ink that criss-crosses the word.
  double sum = 0;
  const int trials = 8;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<TracePoint> scribble;
    for (int i = 0; i < 40; ++i)
      scribble.push_back({rng.uniform(0, kCanvasWidth), rng.uniform(0, kCanvasHeight), true});
    const auto s = score_writing(gold, scribble);
    report("random scribble", s);
    EXPECT_LT(s.score, -0.8);
    sum += s.score;
  }
  EXPECT_LT(sum / trials, -0.88);
  // A random walk of the gold's length around the word's area.
  std::vector<TracePoint> walk{{250, 150, true}};
  for (int i = 0; i < 2000; ++i) {
    const double a = rng.uniform(0, 2 * M_PI);
    walk.push_back({std::clamp(walk.back().x + std::cos(a), 0.0, 500.0),
                    std::clamp(walk.back().y + std::sin(a), 0.0, 300.0), true});
  }
  const auto s = score_writing(gold, walk);
  report("random walk", s);
  EXPECT_LT(s.score, -0.9);
}

TEST(WritingScore, IndependentOfSamplingRate) {
  const auto gold = gold_points("b-a-t-^-");
  for (double speed : {100.0, 300.0}) {
    const auto slow = score_writing(gold, sampled_along(gold, speed, 30));
    const auto fast = score_writing(gold, sampled_along(gold, speed, 240));
    const auto fast_infilled = score_writing(gold, infill_trace({sampled_along(gold, speed, 240), {}}).points);
    report("30 Hz", slow);
    report("240 Hz", fast);
    EXPECT_NEAR(slow.score, fast.score, 0.01);
    EXPECT_NEAR(fast.score, fast_infilled.score, 1e-9);
    EXPECT_GT(fast.score, -0.01);
  }
  // A learner's imperfect trace (offset 4 px, inside the credit ramp) sampled at both rates. At 30 Hz and
  // 200 px/s the samples are 6.7 px apart and their chords cut the letters' tight curves, which moves some
  // ink across the ramp: measured difference 0.012, so the bound here is looser than for on-path traces.
  auto off = gold;
  for (auto& p : off) p.x += 4;
  const auto slow = score_writing(gold, sampled_along(off, 200, 30));
  const auto fast = score_writing(gold, sampled_along(off, 200, 240));
  report("offset 4 px, 30 Hz", slow);
  report("offset 4 px, 240 Hz", fast);
  EXPECT_NEAR(slow.score, fast.score, 0.02);
}

TEST(WritingScore, SymmetricAndBounded) {
  const auto gold = gold_points("ab-c");
  const std::vector<TracePoint> part(gold.begin(), gold.begin() + 600);
  const auto a = score_writing(gold, part);
  const auto b = score_writing(part, gold);
  EXPECT_DOUBLE_EQ(a.recall, b.precision);
  EXPECT_DOUBLE_EQ(a.precision, b.recall);
  EXPECT_DOUBLE_EQ(a.score, b.score);
  EXPECT_GE(a.score, -1.0);
  EXPECT_LE(a.score, 0.0);
}

TEST(WritingScore, EmptyOrLiftedTraceScoresMinusOne) {
  const auto gold = gold_points("a");
  EXPECT_EQ(score_writing(gold, {}).score, -1.0);
  auto lifted = gold;
  for (auto& p : lifted) p.pen = false;  // the pen hovered over the word: no ink
  EXPECT_EQ(score_writing(gold, lifted).score, -1.0);
  EXPECT_THROW(score_writing(lifted, gold), std::invalid_argument);
}

TEST(WritingScore, PenUpMovesAreNotInk) {
  const auto gold = gold_points("P-A", AlphabetKind::Balinese);
  auto all_ink = gold;
  for (auto& p : all_ink) p.pen = true;  // the learner drew the pen-up moves too
  const auto s = score_writing(gold, all_ink);
  report("pen-up moves drawn", s);
  EXPECT_EQ(s.recall, 1.0);
  EXPECT_LT(s.precision, 0.95);
  EXPECT_EQ(score_writing(gold, gold).score, 0.0);
}

TEST(ResampleInk, SpacingRunsAndDots) {
  double length = 0;
  const auto pts =
      resample_ink({{0, 0, true}, {10, 0, true}, {20, 0, false}, {20, 0, true}, {25, 0, false}}, 1.0, &length);
  EXPECT_DOUBLE_EQ(length, 10.0);
  ASSERT_EQ(pts.size(), 11u + 1u);  // 0..10, then the dot at (20, 0)
  EXPECT_EQ(pts.back(), (Point2{20, 0}));
}

}  // namespace
}  // namespace sc::writing
