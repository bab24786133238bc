#include "teaching/stats/sample_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sc::stats {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double sorted_quantile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

}  // namespace

double quantile(std::span<const double> values, double q) {
  if (values.empty()) return kNaN;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted_quantile(sorted, std::clamp(q, 0.0, 1.0));
}

SampleSummary summarise(std::span<const double> values) {
  SampleSummary s;
  s.n = static_cast<int>(values.size());
  if (values.empty()) {
    s.mean = s.sd = s.se = s.min = s.q1 = s.median = s.q3 = s.max = s.whisker_low = s.whisker_high = kNaN;
    return s;
  }
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.n;
  // Two passes: the squared deviations from the mean, not sum(x^2) - n mean^2 (cancellation).
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = s.n < 2 ? kNaN : std::sqrt(squares / (s.n - 1));
  s.se = s.n < 2 ? kNaN : s.sd / std::sqrt(static_cast<double>(s.n));
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  s.q1 = sorted_quantile(sorted, 0.25);
  s.median = sorted_quantile(sorted, 0.5);
  s.q3 = sorted_quantile(sorted, 0.75);
  const double reach = 1.5 * (s.q3 - s.q1);
  s.whisker_low = *std::lower_bound(sorted.begin(), sorted.end(), s.q1 - reach);
  s.whisker_high = *(std::upper_bound(sorted.begin(), sorted.end(), s.q3 + reach) - 1);
  return s;
}

}  // namespace sc::stats
