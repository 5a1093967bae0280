#pragma once
// The median wall time of repeated runs of a piece of work, within a time budget (the ACD
// benchmarks' timing rule, tools/acd_bench.md and tools/acd3d_bench.md).

#include <algorithm>
#include <utility>
#include <vector>

#include "base/stopwatch.h"

namespace acdplan::bench {

/// Median time of repeated runs and the result of the last one.
template <typename Result>
struct Timed {
  Result result;
  double median_ms = 0.0;
  int runs = 0;
};

/// Calls `run` up to `repeats` times and returns the median wall time. A slow cell stops once
/// `budget_ms` is spent and at least `min_runs` (<= repeats) runs are done, so a benchmark stays
/// within minutes while fast cells still get many runs (the machine is shared and noisy). The
/// previous result is destroyed outside the timed region. Fast cells first run untimed for
/// kWarmUpMs: otherwise the first cells of a process run at the idle CPU clock (nazca_monkey SL
/// measured 1.26 ms as the first cell, 0.85 ms after a warm-up).
template <typename Run>
auto TimeRuns(Run&& run, int repeats, double budget_ms, int min_runs) {
  constexpr double kWarmUpMs = 100.0;
  using Result = decltype(run());
  Timed<Result> timed;
  std::vector<double> times;
  double total_ms = 0.0;
  min_runs = std::max(1, std::min(min_runs, repeats));
  auto time_one = [&run, &timed]() {
    const Stopwatch stopwatch;
    Result result = run();
    const double ms = stopwatch.Milliseconds();
    timed.result = std::move(result);
    return ms;
  };
  double warm_up_ms = time_one();
  if (warm_up_ms >= kWarmUpMs) {
    times.push_back(warm_up_ms);  // A slow cell: one cold run among seconds is noise.
    total_ms = warm_up_ms;
  }
  while (times.empty() && warm_up_ms < kWarmUpMs) warm_up_ms += time_one();
  while (static_cast<int>(times.size()) < repeats) {
    if (static_cast<int>(times.size()) >= min_runs && total_ms >= budget_ms) break;
    const double ms = time_one();
    times.push_back(ms);
    total_ms += ms;
  }
  std::sort(times.begin(), times.end());
  const size_t k = times.size();
  timed.median_ms = k % 2 == 1 ? times[k / 2] : 0.5 * (times[k / 2 - 1] + times[k / 2]);
  timed.runs = static_cast<int>(k);
  return timed;
}

}  // namespace acdplan::bench
