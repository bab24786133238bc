#pragma once
// Wilcoxon signed-rank test for paired samples (the paper compares study conditions with it).
#include <vector>

namespace sc {

struct WilcoxonResult {
  int n = 0;            // pairs with a non-zero difference (zero differences are dropped, Wilcoxon's method)
  double w_plus = 0.0;  // sum of ranks of positive differences (a - b > 0)
  double w_minus = 0.0;
  double p_two_sided = 1.0;
  bool exact = false;  // exact null distribution (no ties, n <= 50) or normal approximation
};

// Tests whether the paired differences a[i] - b[i] are symmetric about zero. a and b have equal size.
WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace sc
