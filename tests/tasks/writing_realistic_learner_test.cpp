#include "teaching/tasks/writing_realistic_learner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/writing/word_trajectory.hpp"

namespace sc {
namespace {

const ClassicDrawerGlyphs& glyphs() {
  static const ClassicDrawerGlyphs g = ClassicDrawerGlyphs::load();
  return g;
}

double distance_to_path(const writing::TracePoint& p, const std::vector<writing::TracePoint>& path) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double vx = path[i + 1].x - path[i].x, vy = path[i + 1].y - path[i].y, len2 = vx * vx + vy * vy;
    const double f = len2 > 0 ? std::clamp(((p.x - path[i].x) * vx + (p.y - path[i].y) * vy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - path[i].x - f * vx, p.y - path[i].y - f * vy));
  }
  return best;
}

TEST(WritingRealisticLearner, DrawerSplitKeepsFiveDrawersOutAndThePapersIn) {
  const std::vector<int> train = training_drawers(), unseen = unseen_drawers();
  std::set<int> all(train.begin(), train.end());
  for (int d : unseen) EXPECT_TRUE(all.insert(d).second) << "drawer " << d << " in both";
  EXPECT_EQ(all.size(), 15u);
  EXPECT_EQ(unseen.size(), 5u);
  for (char c : std::string("abcte"))
    EXPECT_LT(writing::default_drawer(writing::AlphabetKind::Classic, c), kFirstUnseenDrawer) << c;
}

TEST(WritingRealisticLearner, ThePapersDrawersWriteTheExpertsWord) {
  const WrittenWord w = written_word(glyphs(), "ab-t^e");
  const writing::WordTrajectory gold = writing::build_word_trajectory(
      writing::GlyphSet::load(writing::AlphabetKind::Classic, writing::omniglot_data_dir()), "ab-t^e");
  EXPECT_EQ(w.points, gold.points());
  EXPECT_EQ(w.symbol_starts, gold.character_starts);
  // Another drawer's 'a' is another shape.
  EXPECT_NE(written_word(glyphs(), "ab-t^e", {7, 0, 0, 0, 0, 0}).points, gold.points());
}

TEST(WritingRealisticLearner, ShapeNoiseKeepsStepIndicesAndStaysWithinTheWobble) {
  const WrittenWord w = written_word(glyphs(), "ba-c");
  Rng rng(3);
  const WrittenWord same = perturbed(w, {}, rng);
  for (std::size_t i = 0; i < w.points.size(); ++i) {
    EXPECT_NEAR(same.points[i].x, w.points[i].x, 1e-9);
    EXPECT_NEAR(same.points[i].y, w.points[i].y, 1e-9);
  }
  Rng rng2(3);
  const WrittenWord wobbly = perturbed(w, {8.0, 0.0}, rng2);
  ASSERT_EQ(wobbly.points.size(), w.points.size());
  EXPECT_EQ(wobbly.symbol_starts, w.symbol_starts);
  double largest = 0.0;
  for (std::size_t i = 0; i < w.points.size(); ++i) {
    const double dx = std::abs(wobbly.points[i].x - w.points[i].x), dy = std::abs(wobbly.points[i].y - w.points[i].y);
    EXPECT_LE(std::max(dx, dy), 8.0 + 1e-9);
    largest = std::max(largest, std::max(dx, dy));
  }
  EXPECT_GT(largest, 2.0);  // it does wobble
}

TEST(WritingRealisticLearner, MouseSamplesLieOnThePathOnTheScreenGridInTimeOrder) {
  const WrittenWord w = written_word(glyphs(), "ct-e");
  Rng rng(5);
  const SampledTrace s = mouse_sampled(w, MouseSampling{}, rng);
  ASSERT_EQ(s.symbol_starts.size(), 4u);
  EXPECT_EQ(s.symbol_starts.front(), 0);
  EXPECT_TRUE(std::is_sorted(s.symbol_starts.begin(), s.symbol_starts.end()));
  EXPECT_LT(s.trace.points.size(), w.points.size());  // the mouse skips pixels
  EXPECT_TRUE(std::is_sorted(s.trace.times.begin(), s.trace.times.end()));
  // Rounding to screen pixels (>= 1.2 per canvas px) plus a screen pixel of tremble during hesitations.
  for (const auto& p : s.trace.points) EXPECT_LT(distance_to_path(p, w.points), 2.0);
  // Each symbol's first sample is near the symbol's first drawn point.
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& p = s.trace.points[static_cast<std::size_t>(s.symbol_starts[k])];
    const auto& q = w.points[static_cast<std::size_t>(w.symbol_starts[k])];
    EXPECT_LT(std::hypot(p.x - q.x, p.y - q.y), 7.5) << "symbol " << k;
  }
}

TEST(WritingRealisticLearner, SameSeedSameTraceAndInfilledStartsPointAtTheSamePlaces) {
  RealisticHand hand;
  hand.noise = {5.0, 0.1};
  hand.drawer_pool = unseen_drawers();
  const SampledTrace a = realistic_trace(glyphs(), "ab-e", hand, 11);
  const SampledTrace b = realistic_trace(glyphs(), "ab-e", hand, 11);
  EXPECT_EQ(a.trace.points, b.trace.points);
  EXPECT_EQ(a.trace.times, b.trace.times);
  EXPECT_NE(realistic_trace(glyphs(), "ab-e", hand, 12).trace.points, a.trace.points);
  const std::vector<int> starts = infilled_symbol_starts(a.trace, a.symbol_starts);
  const writing::TimedTrace infilled = writing::infill_trace(a.trace);
  for (std::size_t k = 0; k < starts.size(); ++k)
    EXPECT_EQ(infilled.points.at(static_cast<std::size_t>(starts[k])),
              a.trace.points[static_cast<std::size_t>(a.symbol_starts[k])]);
}

}  // namespace
}  // namespace sc
