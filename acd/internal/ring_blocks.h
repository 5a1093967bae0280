#pragma once
// Runs of consecutive ring vertices with their bounding boxes: a coarse index for the scans of
// Resolve that visit every vertex or edge of a piece. Internal.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// The bounds of a run of ring vertices: the box of the vertices and of the vertex after the
/// run's last (the box of the edges leaving them), and the largest of a value per vertex over
/// the run (-infinity without values).
struct RunBounds {
  Point2d min, max;
  double top;
};

/// RunBounds of vertices [begin, end) of `ring`; `values`: one per vertex of `ring`, or nullptr.
inline RunBounds BoundRun(const Ring2d& ring, const std::vector<double>* values, int begin,
                          int end) {
  const int n = static_cast<int>(ring.size());
  Point2d lo = ring[end == n ? 0 : end], hi = lo;
  double top = -std::numeric_limits<double>::infinity();
  for (int i = begin; i < end; ++i) {
    lo = lo.cwiseMin(ring[i]);
    hi = hi.cwiseMax(ring[i]);
    if (values != nullptr) top = std::max(top, (*values)[i]);
  }
  return {lo, hi, top};
}

/// The squared distance from `p` to the box [lo, hi], rounded down from the squared distance to
/// every point of the box as computed from the differences of coordinates (rounding is
/// monotone): no vertex in the box has a smaller (u - p).squaredNorm().
inline double BoxSquaredDistance(const Point2d& lo, const Point2d& hi, const Point2d& p) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return dx * dx + dy * dy;
}

/// A ring cut into blocks of kSize consecutive vertices (the last may be shorter). Block b holds
/// vertices [Begin(b), End(b)) and the edges leaving them; its box bounds those vertices and the
/// vertex after End(b) - 1, so it holds the block's edges too. `top` is the largest of a value
/// per vertex over the block (-infinity without values). A scan skips a block whose box keeps
/// clear of what it looks for, or whose top bounds its vertices below what it already has.
class RingBlocks {
 public:
  static constexpr int kSize = 16;
  using Block = RunBounds;

  RingBlocks() = default;
  /// `values`: one per vertex of `ring`, or nullptr.
  RingBlocks(const Ring2d& ring, const std::vector<double>* values) { Assign(ring, values); }

  /// As the constructor, into the storage already held (Resolve keeps one per thread).
  void Assign(const Ring2d& ring, const std::vector<double>* values) {
    const int n = static_cast<int>(ring.size());
    n_ = n;
    blocks_.resize((n + kSize - 1) / kSize);
    for (int b = 0; b < Count(); ++b) blocks_[b] = BoundRun(ring, values, Begin(b), End(b));
  }

  int Count() const { return static_cast<int>(blocks_.size()); }
  /// The storage held, and its release (acd/internal/thread_scratch.h).
  std::size_t HeldBytes() const { return blocks_.capacity() * sizeof(Block); }
  void Release() { std::vector<Block>().swap(blocks_); }
  int Begin(int b) const { return b * kSize; }
  int End(int b) const { return std::min(n_, (b + 1) * kSize); }
  const Block& operator[](int b) const { return blocks_[b]; }

  double SquaredDistance(int b, const Point2d& p) const {
    return BoxSquaredDistance(blocks_[b].min, blocks_[b].max, p);
  }

 private:
  int n_ = 0;
  std::vector<Block> blocks_;
};

/// The holes of a polygon cut into blocks as RingBlocks cuts a ring, without values: a block lies
/// in one hole, holds its vertices [begin, end) and the edges leaving them, and its box bounds
/// those vertices and the one after end - 1. For the scans of Resolve over the holes' edges.
class HoleBlocks {
 public:
  struct Block : RunBounds {
    int hole, begin, end;
  };

  /// Cuts `holes` into blocks, in the storage already held.
  void Assign(const std::vector<Ring2d>& holes) {
    blocks_.clear();
    for (int k = 0; k < static_cast<int>(holes.size()); ++k) {
      const Ring2d& ring = holes[k];
      const int n = static_cast<int>(ring.size());
      for (int begin = 0; begin < n; begin += RingBlocks::kSize) {
        const int end = std::min(n, begin + RingBlocks::kSize);
        blocks_.push_back({BoundRun(ring, nullptr, begin, end), k, begin, end});
      }
    }
  }

  int Count() const { return static_cast<int>(blocks_.size()); }
  const Block& operator[](int b) const { return blocks_[b]; }
  /// The storage held, and its release (acd/internal/thread_scratch.h).
  std::size_t HeldBytes() const { return blocks_.capacity() * sizeof(Block); }
  void Release() { std::vector<Block>().swap(blocks_); }

 private:
  std::vector<Block> blocks_;
};

}  // namespace acdplan::acd::internal
