#pragma once
// One benchmark cell in a child process of its own: its peak memory is its own, and a crash, a
// hang or an exception in it is a result of the cell, not the end of the benchmark.

#include <functional>
#include <string>

namespace acdplan::bench {

/// How a cell's child process ended.
enum class CellStatus {
  kOk,        ///< `work` returned; `output` is what it returned.
  kThrew,     ///< `work` threw; `reason` is the exception's message.
  kCrashed,   ///< Killed by a signal or exited without a result; `reason` says which.
  kTimedOut,  ///< Still running at the deadline, then killed.
};

/// What RunCellProcess() saw of the child.
struct CellOutcome {
  CellStatus status = CellStatus::kCrashed;
  std::string output;  ///< kOk: the text `work` returned.
  /// "" for kOk; else e.g. "threw: <message>", "killed by signal 11 (Segmentation fault)",
  /// "exited with status 7", "timed out after 120 s".
  std::string reason;
  double peak_rss_mib = 0.0;  ///< The child's peak resident set (wait4 ru_maxrss) [MiB].
  double wall_s = 0.0;        ///< From fork to reaping the child [s].
};

/// Forks; the child runs `work` and sends the string it returns back through a pipe, then
/// leaves with _exit (no atexit handlers, no flushing of the parent's inherited buffers). The
/// parent reads until the child closes the pipe or `timeout_s` passes (then SIGKILL), and reaps
/// exactly this child with wait4, which also gives its peak RSS. The child starts as a copy of
/// the parent, so its peak includes the parent's resident pages at the fork: keep the parent
/// small and do the heavy loading in `work`. The caller's stdout and stderr are flushed first.
/// Not thread-safe with respect to other threads of the caller (fork copies only this one).
/// @throws std::runtime_error if pipe() or fork() fails.
CellOutcome RunCellProcess(const std::function<std::string()>& work, double timeout_s);

}  // namespace acdplan::bench
