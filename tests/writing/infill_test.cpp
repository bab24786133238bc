#include "engine/writing/infill.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace sc::writing {
namespace {

// Literal transcription of the reference's loop (insert at i+1, re-check the same i), to pin the order.
std::vector<Point2> infill_by_insertion(std::vector<Point2> p) {
  std::size_t i = 0;
  while (i + 1 < p.size()) {
    if (std::fabs(p[i + 1].y - p[i].y) > 1 || std::fabs(p[i + 1].x - p[i].x) > 1) {
      p.insert(p.begin() + static_cast<std::ptrdiff_t>(i + 1), {(p[i + 1].x + p[i].x) / 2, (p[i + 1].y + p[i].y) / 2});
    } else {
      ++i;
    }
  }
  return p;
}

TEST(Infill, MatchesTheInsertionLoopExactly) {
  Rng rng(7);
  std::vector<Point2> pts;
  for (int i = 0; i < 200; ++i) pts.push_back({rng.uniform(-40, 40), rng.uniform(-40, 40)});
  const auto expected = infill_by_insertion(pts);
  const auto got = infill_reference(pts);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected[i]) << i;  // bitwise equal doubles
}

TEST(Infill, MidpointsOnly) {
  // 4 px to the right: split at 2, then 1 and 3.
  const auto got = infill_reference({{0, 0}, {4, 0}});
  EXPECT_EQ(got, (std::vector<Point2>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}));
  // 3 px diagonal: 1.5 then 0.75 / 2.25: steps of 0.75.
  EXPECT_EQ(infill_reference({{0, 0}, {3, 3}}).size(), 5u);
  EXPECT_EQ(infill_reference({{0, 0}, {1, 1}}).size(), 2u);  // exactly 1 px is not split
  EXPECT_TRUE(infill_reference({}).empty());
}

TEST(Infill, TraceKeepsPenStatesAndInterpolatesTimes) {
  TimedTrace t{{{0, 0, false}, {4, 0, true}, {4, 2, false}}, {0.0, 1.0, 3.0}};
  const auto out = infill_trace(t);
  ASSERT_EQ(out.points.size(), 7u);
  EXPECT_EQ(out.points[1], (TracePoint{1, 0, true}));
  EXPECT_EQ(out.times[1], 0.25);
  EXPECT_EQ(out.points[5], (TracePoint{4, 1, false}));
  EXPECT_EQ(out.times[5], 2.0);
  const auto untimed = infill_trace({t.points, {}});
  EXPECT_TRUE(untimed.times.empty());
  EXPECT_EQ(untimed.points, out.points);
  EXPECT_THROW(infill_trace({t.points, {0.0}}), std::invalid_argument);
}

TEST(Padding, InsertsMidpointsBetweenNeighboursWithTheBugFixed) {
  std::vector<Point2> pts{{0, 0}, {1, 0}, {1, 1}};
  Rng rng(3);
  const auto padded = pad_to_min_points(pts, 10, rng);
  ASSERT_EQ(padded.size(), 10u);
  // With insertion between p_i and p_{i+1} the path never steps backwards: x and y stay monotone here.
  for (std::size_t i = 1; i < padded.size(); ++i) {
    EXPECT_GE(padded[i].x, padded[i - 1].x);
    EXPECT_GE(padded[i].y, padded[i - 1].y);
  }
  EXPECT_EQ(padded.front(), pts.front());
  EXPECT_EQ(padded.back(), pts.back());
  // Long enough: untouched, generator not consumed.
  Rng fresh(3), probe(3);
  EXPECT_EQ(pad_to_min_points(pts, 3, fresh), pts);
  EXPECT_EQ(fresh.next_u64(), probe.next_u64());
}

}  // namespace
}  // namespace sc::writing
