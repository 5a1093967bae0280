#include "bench/stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace acdplan::bench {

std::pair<double, double> WilsonInterval(int successes, int trials, double z) {
  if (successes < 0 || trials < 0 || successes > trials) {
    throw std::invalid_argument("WilsonInterval(): expected 0 <= successes <= trials, got " +
                                std::to_string(successes) + " of " + std::to_string(trials));
  }
  if (trials == 0) return {0.0, 1.0};
  const double n = trials;
  const double p = successes / n;
  const double z2 = z * z;
  const double centre = p + z2 / (2 * n);
  const double spread = z * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  const double scale = 1 + z2 / n;
  // Exact ends at 0 and n (rounding would otherwise give 1e-17 or 0.9999999999999999).
  const double lo = successes == 0 ? 0.0 : (centre - spread) / scale;
  const double hi = successes == trials ? 1.0 : (centre + spread) / scale;
  return {std::max(0.0, lo), std::min(1.0, hi)};
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double h = (values.size() - 1) * q;
  const size_t i = static_cast<size_t>(std::floor(h));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (h - i) * (values[i + 1] - values[i]);
}

std::vector<BenchCaseSummary> SummarizeBenchCases(const std::vector<BenchRecord>& records) {
  std::map<int, std::vector<const BenchRecord*>> by_case;
  for (const BenchRecord& r : records) by_case[r.case_index].push_back(&r);
  std::vector<BenchCaseSummary> summaries;
  for (const auto& [index, runs] : by_case) {
    const BenchRecord& first = *runs.front();
    BenchCaseSummary s;
    s.case_index = index;
    s.what = first.what;
    s.runs = static_cast<int>(runs.size());
    std::vector<double> solved_times, checks, decomposition;
    for (const BenchRecord* r : runs) {
      if (r->solved) {
        ++s.successes;
        solved_times.push_back(r->time_s);
      }
      checks.push_back(static_cast<double>(r->collision_checks));
      decomposition.push_back(r->decomposition_s);
    }
    s.success_rate = static_cast<double>(s.successes) / s.runs;
    s.success_ci95 = WilsonInterval(s.successes, s.runs);
    s.median_time_s = Quantile(solved_times, 0.5);
    s.p90_time_s = Quantile(solved_times, 0.9);
    s.median_collision_checks = Quantile(checks, 0.5);
    s.median_decomposition_s = Quantile(decomposition, 0.5);
    summaries.push_back(s);
  }
  return summaries;
}

}  // namespace acdplan::bench
