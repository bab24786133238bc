#pragma once
// Holm's step-down correction for a family of m tests (Holm 1979): sort the p-values ascending,
// p(1) <= ... <= p(m); the adjusted value of p(i) is max over j <= i of min(1, (m - j + 1) p(j)). A test
// is rejected at level alpha when its adjusted p-value is <= alpha, which is Holm's procedure (stop at the
// first p(i) > alpha / (m - i + 1)); the family-wise error rate stays <= alpha under any dependence.
// Equals statsmodels' multipletests(method="holm") adjusted p-values.
#include <span>
#include <vector>

namespace sc::stats {

// Adjusted p-values in the order of `p_values`. Ties keep their input order.
std::vector<double> holm_adjusted(std::span<const double> p_values);

}  // namespace sc::stats
