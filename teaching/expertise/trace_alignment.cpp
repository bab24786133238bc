#include "teaching/expertise/trace_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sc {
namespace {

double distance(const TracePoint3& a, const TracePoint3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

StepAlignment align_traces(const std::vector<TracePoint3>& expert, const std::vector<TracePoint3>& learner) {
  const std::size_t n = expert.size(), m = learner.size();
  if (n == 0 || m == 0) return {};
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(n * m, kInf);
  auto at = [&](std::size_t i, std::size_t j) -> double& { return cost[i * m + j]; };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      double best = i == 0 && j == 0 ? 0.0 : kInf;
      if (i > 0 && j > 0) best = std::min(best, at(i - 1, j - 1));
      if (i > 0) best = std::min(best, at(i - 1, j));
      if (j > 0) best = std::min(best, at(i, j - 1));
      at(i, j) = best + distance(expert[i], learner[j]);
    }
  }
  StepAlignment path;
  std::size_t i = n - 1, j = m - 1;
  path.push_back({static_cast<int>(i), static_cast<int>(j)});
  while (i > 0 || j > 0) {
    if (i > 0 && j > 0 && at(i - 1, j - 1) <= at(i - 1, j) && at(i - 1, j - 1) <= at(i, j - 1)) {
      --i;
      --j;
    } else if (i > 0 && (j == 0 || at(i - 1, j) <= at(i, j - 1))) {
      --i;
    } else {
      --j;
    }
    path.push_back({static_cast<int>(i), static_cast<int>(j)});
  }
  std::reverse(path.begin(), path.end());
  return path;
}

StepAlignment spread_strided(const StepAlignment& coarse, int stride, int expert_length, int learner_length) {
  if (coarse.empty() || expert_length <= 0 || learner_length <= 0) return {};
  StepAlignment out;
  for (const auto& [a, b] : coarse)
    for (int i = a * stride; i < std::min((a + 1) * stride, expert_length); ++i)
      out.push_back({i, std::min(b * stride + (i - a * stride), learner_length - 1)});
  out.push_back({expert_length - 1, learner_length - 1});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

StepAlignment align_traces_strided(const std::vector<TracePoint3>& expert, const std::vector<TracePoint3>& learner,
                                   int stride) {
  stride = std::max(stride, 1);
  const auto every = [stride](const std::vector<TracePoint3>& points) {
    std::vector<TracePoint3> out;
    for (std::size_t t = 0; t < points.size(); t += static_cast<std::size_t>(stride)) out.push_back(points[t]);
    return out;
  };
  return spread_strided(align_traces(every(expert), every(learner)), stride, static_cast<int>(expert.size()),
                        static_cast<int>(learner.size()));
}

std::pair<int, int> aligned_span(const StepAlignment& path, int begin, int end) {
  int first = -1, last = -1;
  for (const auto& [e, l] : path) {
    if (e < begin || e >= end) continue;
    if (first < 0) first = l;
    last = l;
  }
  return first < 0 ? std::pair{0, 0} : std::pair{first, last + 1};
}

}  // namespace sc
