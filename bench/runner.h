#pragma once
// Runs the cases of a benchmark (or one shard of them), each run in its own child process.

#include <csignal>
#include <functional>
#include <iosfwd>
#include <vector>

#include "bench/record.h"
#include "bench/spec.h"

namespace acdplan::bench {

/// Options for RunBench(); `{}` is valid.
struct BenchRunOptions {
  int runs = 0;      ///< Runs per case; 0: the spec's.
  BenchShard shard;  ///< Which runs to do (default: all).
  int jobs = 1;      ///< Runs in parallel (child processes); >= 1. Times are measured per
                     ///< run; more jobs than free cores inflate them.
  std::ostream* progress = nullptr;  ///< A progress line (runs done / total, elapsed, estimate
                                     ///< left) goes here if set.
  /// Polled between runs; when it becomes non-zero the running runs are killed (and
  /// dropped) and RunBench() returns what finished.
  const volatile std::sig_atomic_t* stop = nullptr;
  double checkpoint_s = 30.0;  ///< Call `checkpoint` at most this often [s].
  std::function<void(const std::vector<BenchRecord>&)> checkpoint;  ///< Finished runs so far.
};

/// What RunBench() did.
struct BenchRunOutcome {
  std::vector<BenchRecord> records;  ///< Finished runs in the global order.
  std::uint64_t planned = 0;         ///< Runs of the shard.
  bool interrupted = false;          ///< `stop` was raised before all runs finished.
  double wall_s = 0.0;
};

/// Checks that each robot fits at each world's start and goal, then runs the shard's runs
/// (BenchRunsOfShard). Each run is PlanScenario() on the world with the robot, sampler,
/// planner, budget and the run's seed, in a child process that seeds OMPL's global generator
/// with it first (only these children are reaped: waitpid on their pids, never on -1, so the
/// caller's own children keep their exit statuses): a run's result depends on its seed only, not on
/// which runs came before in the same process, so shards reproduce the unsharded benchmark. A child
/// also gets a watchdog (SIGALRM at 10 x the time limit + 60 s, or 600 s for a sample budget). acd
/// runs keep the decomposition in their time; the other samplers do not use it, so it is taken out
/// of theirs (and their decomposition_s is 0).
/// @throws InputError "<bench file>: worlds ...: robot <name>: start: ..." if a robot
///         collides at a start or goal, or if a run reports bad input.
BenchRunOutcome RunBench(const BenchSpec& spec, const BenchRunOptions& options = {});

}  // namespace acdplan::bench
