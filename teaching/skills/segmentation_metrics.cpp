#include "teaching/skills/segmentation_metrics.hpp"

#include <algorithm>
#include <cstdlib>
#include <tuple>

namespace sc {

double BoundaryScore::precision() const {
  const int n = true_positives + false_positives;
  return n == 0 ? 1.0 : static_cast<double>(true_positives) / n;
}

double BoundaryScore::recall() const {
  const int n = true_positives + false_negatives;
  return n == 0 ? 1.0 : static_cast<double>(true_positives) / n;
}

double BoundaryScore::f1() const {
  const double p = precision(), r = recall();
  return p + r == 0.0 ? 0.0 : 2.0 * p * r / (p + r);
}

BoundaryScore& BoundaryScore::operator+=(const BoundaryScore& o) {
  true_positives += o.true_positives;
  false_positives += o.false_positives;
  false_negatives += o.false_negatives;
  return *this;
}

std::vector<int> interior_boundaries(const Segmentation& segmentation) {
  std::vector<int> out;
  for (std::size_t i = 0; i + 1 < segmentation.segments.size(); ++i) out.push_back(segmentation.segments[i].end);
  return out;
}

BoundaryScore score_boundaries(const std::vector<int>& predicted, const std::vector<int>& truth, int tolerance) {
  std::vector<std::tuple<int, std::size_t, std::size_t>> pairs;  // distance, predicted, true
  for (std::size_t i = 0; i < predicted.size(); ++i)
    for (std::size_t j = 0; j < truth.size(); ++j) {
      const int d = std::abs(predicted[i] - truth[j]);
      if (d <= tolerance) pairs.emplace_back(d, i, j);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used_p(predicted.size()), used_t(truth.size());
  BoundaryScore s;
  for (const auto& [d, i, j] : pairs) {
    if (used_p[i] || used_t[j]) continue;
    used_p[i] = used_t[j] = true;
    ++s.true_positives;
  }
  s.false_positives = static_cast<int>(predicted.size()) - s.true_positives;
  s.false_negatives = static_cast<int>(truth.size()) - s.true_positives;
  return s;
}

}  // namespace sc
