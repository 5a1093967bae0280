// RunCellProcess: a cell's result, exception, crash and hang each come back as an outcome, and
// the peak memory is the child's own.

#include "bench/cell_process.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace acdplan::bench {
namespace {

TEST(CellProcess, ReturnsTheChildsResult) {
  // Larger than a pipe's buffer: the parent must read while the child writes.
  const std::string big(1 << 20, 'x');
  const CellOutcome outcome = RunCellProcess([&] { return big + "!"; }, 60);
  EXPECT_EQ(outcome.status, CellStatus::kOk);
  EXPECT_EQ(outcome.reason, "");
  EXPECT_EQ(outcome.output.size(), big.size() + 1);
  EXPECT_EQ(outcome.output.back(), '!');
  EXPECT_GT(outcome.peak_rss_mib, 0.0);
}

TEST(CellProcess, MeasuresTheChildsPeakMemory) {
  const CellOutcome small = RunCellProcess([] { return std::string("ok"); }, 60);
  const CellOutcome large = RunCellProcess(
      [] {
        std::vector<char> block(size_t{256} << 20);
        std::memset(block.data(), 1, block.size());  // Touched: resident.
        return std::string(1, block[block.size() / 2]);
      },
      60);
  ASSERT_EQ(large.status, CellStatus::kOk);
  EXPECT_GT(large.peak_rss_mib, small.peak_rss_mib + 200);
  // The parent did not grow: the next small child is small again.
  const CellOutcome again = RunCellProcess([] { return std::string("ok"); }, 60);
  EXPECT_LT(again.peak_rss_mib, small.peak_rss_mib + 64);
}

TEST(CellProcess, AnExceptionIsAnOutcome) {
  const CellOutcome outcome =
      RunCellProcess([]() -> std::string { throw std::runtime_error("no volume"); }, 60);
  EXPECT_EQ(outcome.status, CellStatus::kThrew);
  EXPECT_EQ(outcome.reason, "threw: no volume");
}

TEST(CellProcess, ACrashIsAnOutcome) {
  const CellOutcome killed = RunCellProcess(
      []() -> std::string {
        raise(SIGKILL);
        return "unreachable";
      },
      60);
  EXPECT_EQ(killed.status, CellStatus::kCrashed);
  EXPECT_EQ(killed.reason, "killed by signal 9 (Killed)");
  const CellOutcome exited = RunCellProcess(
      []() -> std::string {
        _exit(7);
        return "unreachable";
      },
      60);
  EXPECT_EQ(exited.status, CellStatus::kCrashed);
  EXPECT_EQ(exited.reason, "exited with status 7");
}

TEST(CellProcess, AHangIsKilledAtTheDeadline) {
  const CellOutcome outcome = RunCellProcess(
      []() -> std::string {
        for (;;) pause();
      },
      0.2);
  EXPECT_EQ(outcome.status, CellStatus::kTimedOut);
  EXPECT_EQ(outcome.reason, "timed out after 0.2 s");
  EXPECT_GE(outcome.wall_s, 0.2);
}

}  // namespace
}  // namespace acdplan::bench
