#include "teaching/expertise/trace_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace sc {
namespace {

double distance(const TracePoint3& a, const TracePoint3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

// The accumulated costs are kept for two rows only, and each cell's predecessor as one byte: the same choice the
// spec's backtracking makes from the finished costs (they are final when the cell is computed), at an eighth of
// the memory a full cost matrix took (a writing pre-test aligns ~1000 x 1000 points per reference and word).
StepAlignment align_traces(const std::vector<TracePoint3>& expert, const std::vector<TracePoint3>& learner) {
  const std::size_t n = expert.size(), m = learner.size();
  if (n == 0 || m == 0) return {};
  enum Step : unsigned char { kDiagonal, kExpert, kLearner };  // (i-1, j-1), (i-1, j), (i, j-1)
  std::vector<unsigned char> from(n * m);
  std::vector<double> previous(m), current(m);
  for (std::size_t i = 0; i < n; ++i) {
    unsigned char* row_from = from.data() + i * m;
    for (std::size_t j = 0; j < m; ++j) {
      double best = 0.0;
      if (i == 0 && j > 0) {
        best = current[j - 1];
        row_from[j] = kLearner;
      } else if (i > 0 && j == 0) {
        best = previous[0];
        row_from[j] = kExpert;
      } else if (i > 0) {
        const double diagonal = previous[j - 1], up = previous[j], left = current[j - 1];
        if (diagonal <= up && diagonal <= left) {
          best = diagonal;
          row_from[j] = kDiagonal;
        } else if (up <= left) {
          best = up;
          row_from[j] = kExpert;
        } else {
          best = left;
          row_from[j] = kLearner;
        }
      }
      current[j] = best + distance(expert[i], learner[j]);
    }
    std::swap(previous, current);
  }
  StepAlignment path;
  std::size_t i = n - 1, j = m - 1;
  path.push_back({static_cast<int>(i), static_cast<int>(j)});
  while (i > 0 || j > 0) {
    const unsigned char step = from[i * m + j];
    if (step != kLearner) --i;
    if (step != kExpert) --j;
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
