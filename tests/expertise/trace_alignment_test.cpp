#include "teaching/expertise/trace_alignment.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

std::vector<TracePoint3> line(const std::vector<double>& xs) {
  std::vector<TracePoint3> out;
  for (double x : xs) out.push_back({x, 0.0, 0.0});
  return out;
}

TEST(TraceAlignment, IdenticalTracesAlignStepByStep) {
  const StepAlignment path = align_traces(line({0, 1, 2, 3}), line({0, 1, 2, 3}));
  EXPECT_EQ(path, (StepAlignment{{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
}

TEST(TraceAlignment, ASlowerLearnerSpendsTwoStepsOnEachExpertStep) {
  const StepAlignment path = align_traces(line({0, 2, 4}), line({0, 0.5, 2, 2.5, 4, 4}));
  EXPECT_EQ(aligned_span(path, 0, 1), (std::pair{0, 2}));
  EXPECT_EQ(aligned_span(path, 1, 2), (std::pair{2, 4}));
  EXPECT_EQ(aligned_span(path, 2, 3), (std::pair{4, 6}));
  EXPECT_EQ(aligned_span(path, 1, 3), (std::pair{2, 6}));
  // The path runs from (0, 0) to the ends, never backwards.
  EXPECT_EQ(path.front(), (std::pair{0, 0}));
  EXPECT_EQ(path.back(), (std::pair{2, 5}));
  for (std::size_t k = 1; k < path.size(); ++k) {
    EXPECT_GE(path[k].first, path[k - 1].first);
    EXPECT_GE(path[k].second, path[k - 1].second);
  }
}

TEST(TraceAlignment, EmptyTracesGiveNoPath) {
  EXPECT_TRUE(align_traces({}, line({1})).empty());
  EXPECT_EQ(aligned_span({}, 0, 3), (std::pair{0, 0}));
}

TEST(TraceAlignment, AStridedAlignmentOfIdenticalTracesIsStepByStep) {
  std::vector<double> xs;
  for (int t = 0; t < 23; ++t) xs.push_back(t);
  StepAlignment identity;
  for (int t = 0; t < 23; ++t) identity.push_back({t, t});
  EXPECT_EQ(align_traces_strided(line(xs), line(xs), 4), identity);
  EXPECT_EQ(align_traces_strided(line(xs), line(xs), 1), align_traces(line(xs), line(xs)));
}

TEST(TraceAlignment, AStridedPathIsSpreadOverTheStepsOfEachBlock) {
  // Blocks of 3: expert block 0 with learner block 0, expert block 1 with learner blocks 1 and 2.
  EXPECT_EQ(spread_strided({{0, 0}, {1, 1}, {1, 2}}, 3, 5, 8),
            (StepAlignment{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {3, 6}, {4, 4}, {4, 7}}));
  // Learner steps past its end are clamped; the last steps always pair.
  EXPECT_EQ(spread_strided({{0, 0}, {1, 1}}, 3, 6, 4), (StepAlignment{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 3}, {5, 3}}));
  EXPECT_TRUE(spread_strided({}, 3, 6, 4).empty());
}

}  // namespace
}  // namespace sc
