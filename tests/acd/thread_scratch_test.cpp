// ScratchScope: a thread's scratch storage survives the call while small (so the next call does
// not allocate) and is released when it grew past kRetainedScratchBytes (so a thread keeps no
// large buffer after a large input); for vectors and for classes with HeldBytes()/Release().

#include "acd/internal/thread_scratch.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace acdplan::acd::internal {
namespace {

TEST(ThreadScratchTest, KeepsSmallVectorsAndReleasesLargeOnes) {
  std::vector<double> small, large;
  const std::size_t small_count = 1000;
  const std::size_t large_count = kRetainedScratchBytes / sizeof(double) + 1;
  {
    const ScratchScope small_scope(small), large_scope(large);
    small.resize(small_count);
    large.resize(large_count);
  }
  EXPECT_GE(small.capacity(), small_count);
  EXPECT_EQ(large.capacity(), 0u);
}

// A class that reports what it holds, as RingBlocks and EdgeGrid do.
struct Held {
  std::size_t bytes = 0;
  int released = 0;
  std::size_t HeldBytes() const { return bytes; }
  void Release() {
    bytes = 0;
    ++released;
  }
};

TEST(ThreadScratchTest, ReleasesAClassThatHoldsTooMuch) {
  Held kept, dropped;
  {
    const ScratchScope kept_scope(kept);
    const ScratchScope dropped_scope(dropped);
    kept.bytes = kRetainedScratchBytes;
    dropped.bytes = kRetainedScratchBytes + 1;
  }
  EXPECT_EQ(kept.released, 0);
  EXPECT_EQ(dropped.released, 1);
  EXPECT_EQ(dropped.bytes, 0u);
}

}  // namespace
}  // namespace acdplan::acd::internal
