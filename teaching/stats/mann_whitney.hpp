#pragma once
// The two-sided Mann-Whitney U test of two independent samples, computed as scipy.stats.mannwhitneyu
// does by default (scipy >= 1.7: use_continuity=True, alternative="two-sided", method="auto"):
//  - U is the first sample's statistic: U1 = R1 - n1 (n1 + 1) / 2 with R1 the sum of its mid-ranks in the
//    pooled sample, i.e. the number of pairs (x, y) with x > y plus half the pairs with x == y;
//  - "auto" takes the exact null distribution when there are no ties and at least one sample has 8 values
//    or fewer, and the normal approximation otherwise;
//  - exact: p = 2 P(U >= max(U1, U2)) under H0 (all C(n1 + n2, n1) rank splits equally likely), at most 1;
//  - normal approximation: z = (max(U1, U2) - n1 n2 / 2 - 1/2) / sigma with the tie-corrected
//    sigma^2 = n1 n2 / 12 ((n + 1) - sum(t^3 - t) / (n (n - 1))), p = 2 (1 - Phi(z)), at most 1.
#include <span>
#include <string_view>

namespace sc::stats {

enum class MannWhitneyMethod { Auto, Exact, Asymptotic };

struct MannWhitneyResult {
  double u = 0.0;                                       // U of the first sample
  double p = 1.0;                                       // two-sided p-value
  MannWhitneyMethod method = MannWhitneyMethod::Exact;  // the one used (never Auto)
  double z = 0.0;       // asymptotic: the continuity-corrected z of max(U1, U2); exact: NaN
  bool ties = false;    // some value occurs more than once in the pooled sample
  double effect = 0.0;  // U / (n1 n2): the probability that a value of the first sample beats one of the second
                        // (ties count half), the common-language effect size; 0.5 = no difference
};

// Throws std::invalid_argument when a sample is empty or holds a non-finite value.
MannWhitneyResult mann_whitney_u(std::span<const double> x, std::span<const double> y,
                                 MannWhitneyMethod method = MannWhitneyMethod::Auto);
// "exact" or "normal approximation (tie and continuity corrected)".
std::string_view method_description(MannWhitneyMethod method);
// P(U >= u) under H0 without ties, from the exact distribution of U for sample sizes n1 and n2.
double exact_u_upper_tail(int n1, int n2, double u);

}  // namespace sc::stats
