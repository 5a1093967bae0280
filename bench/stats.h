#pragma once
// Statistics of benchmark runs: the Wilson score interval and per-case summaries.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bench/record.h"

namespace acdplan::bench {

/// The Wilson score interval [lo, hi] for `successes` out of `trials` at normal quantile `z`
/// (1.959964 for 95%): (p + z^2/2n +- z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n), p = k/n
/// (E. B. Wilson, JASA 22(158), 1927). Unlike the normal approximation it stays inside [0, 1]
/// and is informative at 0 and n successes. trials == 0 gives [0, 1].
/// @throws std::invalid_argument unless 0 <= successes <= trials.
std::pair<double, double> WilsonInterval(int successes, int trials, double z = 1.959963984540054);

/// The q-quantile (q in [0, 1]) of `values` by linear interpolation between order statistics
/// (type 7, as numpy's default); NaN for no values.
double Quantile(std::vector<double> values, double q);

/// One case's outcome over its runs.
struct BenchCaseSummary {
  int case_index = 0;
  CaseDescription what;  ///< The case.
  int runs = 0, successes = 0;
  double success_rate = 0.0;
  std::pair<double, double> success_ci95{0.0, 1.0};  ///< Wilson.
  /// Over the solved runs (time to solve, decomposition included for acd); NaN if none.
  double median_time_s = 0.0, p90_time_s = 0.0;
  double median_collision_checks = 0.0;  ///< Over all runs.
  double median_decomposition_s = 0.0;   ///< Over all runs (0 for samplers other than acd).
};

/// One summary per case present in `records`, in case order.
std::vector<BenchCaseSummary> SummarizeBenchCases(const std::vector<BenchRecord>& records);

}  // namespace acdplan::bench
