#include "bench/cell_process.h"

#include <poll.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <stdexcept>

#include "base/format.h"
#include "base/stopwatch.h"

namespace acdplan::bench {

namespace {

/// Writes all of `text` to `fd`; false if the pipe broke.
bool WriteAll(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

/// The child's side: never returns. Exit status 0 with the result on the pipe, 3 with an
/// exception's message on it.
[[noreturn]] void RunChild(const std::function<std::string()>& work, int fd) {
  int status = 0;
  std::string text;
  try {
    text = work();
  } catch (const std::exception& error) {
    text = error.what();
    status = 3;
  } catch (...) {
    text = "unknown exception";
    status = 3;
  }
  if (!WriteAll(fd, text)) status = 4;
  close(fd);
  _exit(status);
}

}  // namespace

CellOutcome RunCellProcess(const std::function<std::string()>& work, double timeout_s) {
  // Inherited unflushed output would be written twice (once by each process) otherwise.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe(): ") + std::strerror(errno));
  const Stopwatch stopwatch;
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error(std::string("fork(): ") + std::strerror(error));
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(work, fds[1]);
  }
  close(fds[1]);

  CellOutcome outcome;
  std::string received;
  bool timed_out = false;
  char buffer[65536];
  for (;;) {
    const double left_ms = 1e3 * timeout_s - stopwatch.Milliseconds();
    if (left_ms <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min(left_ms + 1.0, 1e9)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;  // Timeout: the loop's test decides.
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // The child closed its end (done, or dead).
    received.append(buffer, static_cast<size_t>(n));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  outcome.wall_s = stopwatch.Seconds();
  outcome.peak_rss_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: KiB.
  if (timed_out) {
    outcome.status = CellStatus::kTimedOut;
    outcome.reason = "timed out after " + FormatSignificant(timeout_s, 6) + " s";
  } else if (WIFSIGNALED(status)) {
    outcome.status = CellStatus::kCrashed;
    const int signal = WTERMSIG(status);
    outcome.reason = "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    outcome.status = CellStatus::kOk;
    outcome.output = std::move(received);
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 3) {
    outcome.status = CellStatus::kThrew;
    outcome.reason = "threw: " + received;
  } else {
    outcome.status = CellStatus::kCrashed;
    outcome.reason = "exited with status " + std::to_string(WEXITSTATUS(status));
  }
  return outcome;
}

}  // namespace acdplan::bench
