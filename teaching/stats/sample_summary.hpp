#pragma once
// What a report says about one sample: its size, mean, standard deviation (n - 1 in the denominator, as
// scipy.stats.sem and the usual "mean +- s.e." bars use), standard error of the mean, and the quartiles a
// box plot draws (linear interpolation between order statistics: numpy's default, Hyndman-Fan type 7) with
// Tukey's whiskers (the most extreme values within 1.5 interquartile ranges of the box; values beyond are
// outliers, drawn as points).
#include <span>

namespace sc::stats {

struct SampleSummary {
  int n = 0;
  double mean = 0.0;
  double sd = 0.0;  // NaN when n < 2
  double se = 0.0;  // sd / sqrt(n); NaN when n < 2
  double min = 0.0, q1 = 0.0, median = 0.0, q3 = 0.0, max = 0.0;
  double whisker_low = 0.0, whisker_high = 0.0;
};

// All fields NaN (n = 0) for an empty sample.
SampleSummary summarise(std::span<const double> values);
// The q-quantile (0 <= q <= 1) of `values` with type-7 interpolation; NaN for an empty sample.
double quantile(std::span<const double> values, double q);

}  // namespace sc::stats
