#pragma once
// Runs of consecutive ring vertices with their bounding boxes: a coarse index for the scans of
// Resolve that visit every vertex or edge of a piece. Internal.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// A ring cut into blocks of kSize consecutive vertices (the last may be shorter). Block b holds
/// vertices [Begin(b), End(b)) and the edges leaving them; its box bounds those vertices and the
/// vertex after End(b) - 1, so it holds the block's edges too. `top` is the largest of a value
/// per vertex over the block (-infinity without values). A scan skips a block whose box keeps
/// clear of what it looks for, or whose top bounds its vertices below what it already has.
class RingBlocks {
 public:
  static constexpr int kSize = 16;
  struct Block {
    Point2d min, max;
    double top;
  };

  RingBlocks() = default;
  /// `values`: one per vertex of `ring`, or nullptr.
  RingBlocks(const Ring2d& ring, const std::vector<double>* values) { Assign(ring, values); }

  /// As the constructor, into the storage already held (Resolve keeps one per thread).
  void Assign(const Ring2d& ring, const std::vector<double>* values) {
    const int n = static_cast<int>(ring.size());
    n_ = n;
    blocks_.resize((n + kSize - 1) / kSize);
    for (int b = 0; b < Count(); ++b) {
      const int begin = Begin(b), end = End(b);
      Point2d lo = ring[end == n ? 0 : end], hi = lo;
      double top = -std::numeric_limits<double>::infinity();
      for (int i = begin; i < end; ++i) {
        lo = lo.cwiseMin(ring[i]);
        hi = hi.cwiseMax(ring[i]);
        if (values != nullptr) top = std::max(top, (*values)[i]);
      }
      blocks_[b] = {lo, hi, top};
    }
  }

  int Count() const { return static_cast<int>(blocks_.size()); }
  /// The storage held, and its release (acd/internal/thread_scratch.h).
  std::size_t HeldBytes() const { return blocks_.capacity() * sizeof(Block); }
  void Release() { std::vector<Block>().swap(blocks_); }
  int Begin(int b) const { return b * kSize; }
  int End(int b) const { return std::min(n_, (b + 1) * kSize); }
  const Block& operator[](int b) const { return blocks_[b]; }

  /// The squared distance from `p` to block b's box, rounded down from the squared distance to
  /// each of its vertices as computed from the differences of coordinates (rounding is monotone).
  double SquaredDistance(int b, const Point2d& p) const {
    const Block& block = blocks_[b];
    const double dx = std::max({block.min.x() - p.x(), 0.0, p.x() - block.max.x()});
    const double dy = std::max({block.min.y() - p.y(), 0.0, p.y() - block.max.y()});
    return dx * dx + dy * dy;
  }

 private:
  int n_ = 0;
  std::vector<Block> blocks_;
};

}  // namespace acdplan::acd::internal
