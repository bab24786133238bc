#include "teaching/expertise/trace_alignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/rng.hpp"

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

double distance(const TracePoint3& a, const TracePoint3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The spec read literally: the whole cost matrix, then the backtracking from its finished values.
StepAlignment spec_alignment(const std::vector<TracePoint3>& e, const std::vector<TracePoint3>& l) {
  const std::size_t n = e.size(), m = l.size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> c(n * m, inf);
  const auto at = [&](std::size_t i, std::size_t j) -> double& { return c[i * m + j]; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      double best = i == 0 && j == 0 ? 0.0 : inf;
      if (i > 0 && j > 0) best = std::min(best, at(i - 1, j - 1));
      if (i > 0) best = std::min(best, at(i - 1, j));
      if (j > 0) best = std::min(best, at(i, j - 1));
      at(i, j) = best + distance(e[i], l[j]);
    }
  StepAlignment path{{static_cast<int>(n - 1), static_cast<int>(m - 1)}};
  for (std::size_t i = n - 1, j = m - 1; i > 0 || j > 0; path.push_back({static_cast<int>(i), static_cast<int>(j)})) {
    if (i > 0 && j > 0 && at(i - 1, j - 1) <= at(i - 1, j) && at(i - 1, j - 1) <= at(i, j - 1)) {
      --i;
      --j;
    } else if (i > 0 && (j == 0 || at(i - 1, j) <= at(i, j - 1))) {
      --i;
    } else {
      --j;
    }
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// Random traces on a coarse grid, so that equal costs (the ties the spec orders) are common.
TEST(TraceAlignment, TheSamePathAsTheSpecsFullMatrixTiesIncluded) {
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<TracePoint3> e(1 + rng.below(30)), l(1 + rng.below(30));
    for (auto* trace : {&e, &l})
      for (TracePoint3& p : *trace) p = {static_cast<double>(rng.below(4)), static_cast<double>(rng.below(4)), 0.0};
    ASSERT_EQ(align_traces(e, l), spec_alignment(e, l)) << "trial " << trial;
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
