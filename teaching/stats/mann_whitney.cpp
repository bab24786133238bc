#include "teaching/stats/mann_whitney.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace sc::stats {
namespace {

struct PooledRanks {
  double rank_sum_x = 0.0;  // sum of the mid-ranks of the first sample
  double tie_term = 0.0;    // sum over groups of equal values of t^3 - t
  bool ties = false;
};

PooledRanks pooled_ranks(std::span<const double> x, std::span<const double> y) {
  std::vector<std::pair<double, bool>> pooled;  // value, belongs to x
  for (double v : x) pooled.emplace_back(v, true);
  for (double v : y) pooled.emplace_back(v, false);
  std::sort(pooled.begin(), pooled.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  PooledRanks out;
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double t = static_cast<double>(j - i);
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;  // ranks i+1 .. j
    for (std::size_t k = i; k < j; ++k) out.rank_sum_x += pooled[k].second ? mid_rank : 0.0;
    if (t > 1) {
      out.ties = true;
      out.tie_term += t * t * t - t;
    }
    i = j;
  }
  return out;
}

void require_sample(std::span<const double> sample, const char* which) {
  if (sample.empty()) throw std::invalid_argument(std::string("Mann-Whitney U: the ") + which + " sample is empty");
  for (double v : sample)
    if (!std::isfinite(v))
      throw std::invalid_argument(std::string("Mann-Whitney U: the ") + which + " sample holds a non-finite value");
}

}  // namespace

double exact_u_upper_tail(int n1, int n2, double u) {
  // counts[k][s]: subsets of k of the ranks seen so far with rank sum s; U = S - n1 (n1 + 1) / 2.
  const int n = n1 + n2;
  const int max_sum = n1 * (2 * n - n1 + 1) / 2;
  std::vector<std::vector<double>> counts(static_cast<std::size_t>(n1) + 1,
                                          std::vector<double>(static_cast<std::size_t>(max_sum) + 1, 0.0));
  counts[0][0] = 1.0;
  for (int r = 1; r <= n; ++r)
    for (int k = std::min(r, n1); k >= 1; --k)
      for (int s = max_sum; s >= r; --s) counts[k][s] += counts[k - 1][s - r];
  const int offset = n1 * (n1 + 1) / 2;
  double total = 0.0, tail = 0.0;
  for (int s = offset; s <= max_sum; ++s) {
    total += counts[n1][s];
    if (s - offset >= u - 1e-9) tail += counts[n1][s];
  }
  return tail / total;
}

MannWhitneyResult mann_whitney_u(std::span<const double> x, std::span<const double> y, MannWhitneyMethod method) {
  require_sample(x, "first");
  require_sample(y, "second");
  const double n1 = static_cast<double>(x.size()), n2 = static_cast<double>(y.size()), n = n1 + n2;
  const PooledRanks ranks = pooled_ranks(x, y);
  MannWhitneyResult result;
  result.u = ranks.rank_sum_x - n1 * (n1 + 1) / 2.0;
  result.ties = ranks.ties;
  result.effect = result.u / (n1 * n2);
  const double u_max = std::max(result.u, n1 * n2 - result.u);
  if (method == MannWhitneyMethod::Auto)
    method = (x.size() > 8 && y.size() > 8) || ranks.ties ? MannWhitneyMethod::Asymptotic : MannWhitneyMethod::Exact;
  result.method = method;
  if (method == MannWhitneyMethod::Exact) {
    result.z = std::numeric_limits<double>::quiet_NaN();
    result.p = std::min(1.0, 2.0 * exact_u_upper_tail(static_cast<int>(x.size()), static_cast<int>(y.size()), u_max));
    return result;
  }
  const double variance = n1 * n2 / 12.0 * ((n + 1.0) - ranks.tie_term / (n * (n - 1.0)));
  if (variance <= 0.0) {  // every value equal: no evidence of any difference
    result.z = 0.0;
    result.p = 1.0;
    return result;
  }
  result.z = (u_max - n1 * n2 / 2.0 - 0.5) / std::sqrt(variance);
  result.p = std::min(1.0, std::erfc(result.z / std::sqrt(2.0)));  // 2 (1 - Phi(z))
  return result;
}

std::string_view method_description(MannWhitneyMethod method) {
  switch (method) {
    case MannWhitneyMethod::Exact:
      return "exact";
    case MannWhitneyMethod::Asymptotic:
      return "normal approximation (tie and continuity corrected)";
    case MannWhitneyMethod::Auto:
      return "auto";
  }
  return "?";
}

}  // namespace sc::stats
