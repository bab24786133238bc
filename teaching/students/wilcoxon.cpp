#include "teaching/students/wilcoxon.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sc {
namespace {

// P(W+ <= w) under H0 for n untied ranks 1..n, by counting subsets with each rank sum.
double exact_cdf(int n, int w) {
  const int max_sum = n * (n + 1) / 2;
  std::vector<double> count(static_cast<std::size_t>(max_sum) + 1, 0.0);
  count[0] = 1.0;
  for (int r = 1; r <= n; ++r)
    for (int s = max_sum; s >= r; --s) count[static_cast<std::size_t>(s)] += count[static_cast<std::size_t>(s - r)];
  double below = 0.0;
  for (int s = 0; s <= std::min(w, max_sum); ++s) below += count[static_cast<std::size_t>(s)];
  return below / std::ldexp(1.0, n);
}

}  // namespace

WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("wilcoxon_signed_rank: samples differ in size");
  std::vector<double> diff;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] - b[i] != 0.0) diff.push_back(a[i] - b[i]);
  WilcoxonResult result;
  result.n = static_cast<int>(diff.size());
  if (result.n == 0) return result;

  std::vector<std::size_t> order(diff.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto i, auto j) { return std::fabs(diff[i]) < std::fabs(diff[j]); });
  std::vector<double> rank(diff.size());
  bool ties = false;
  double tie_term = 0.0;  // sum of (t^3 - t) over tie groups, for the variance correction
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && std::fabs(diff[order[j + 1]]) == std::fabs(diff[order[i]])) ++j;
    const double average = (static_cast<double>(i + j) + 2.0) / 2.0;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = average;
    const double t = static_cast<double>(j - i + 1);
    if (t > 1) ties = true;
    tie_term += t * t * t - t;
    i = j + 1;
  }
  for (std::size_t i = 0; i < diff.size(); ++i) (diff[i] > 0 ? result.w_plus : result.w_minus) += rank[i];

  const int n = result.n;
  const double w = std::min(result.w_plus, result.w_minus);
  if (!ties && n <= 50) {
    result.exact = true;
    result.p_two_sided = std::min(1.0, 2.0 * exact_cdf(n, static_cast<int>(std::lround(w))));
    return result;
  }
  const double mean = n * (n + 1) / 4.0;
  const double variance = n * (n + 1) * (2.0 * n + 1) / 24.0 - tie_term / 48.0;
  if (variance <= 0) return result;
  const double z = (std::fabs(w - mean) - 0.5) / std::sqrt(variance);  // continuity correction
  result.p_two_sided = std::min(1.0, std::erfc(std::max(z, 0.0) / std::sqrt(2.0)));
  return result;
}

}  // namespace sc
