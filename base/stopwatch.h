#pragma once
// Wall time of a piece of work, on the monotonic clock.

#include <chrono>

namespace acdplan {

/// Measures the wall time since construction or the last Restart(). Not affected by changes
/// of the system clock.
class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void Restart() { start_ = Clock::now(); }
  /// Elapsed time [s].
  double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// Elapsed time [ms].
  double Milliseconds() const { return 1e3 * Seconds(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace acdplan
