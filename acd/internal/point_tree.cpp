#include "acd/internal/point_tree.h"

#include <algorithm>
#include <utility>

namespace acdplan::acd::internal {
namespace {

constexpr int kRunLength = 16;  // Points per run.
constexpr int kLeafRuns = 2;    // Runs per leaf.

}  // namespace

PointTree::PointTree(std::vector<Point2d> points, const std::vector<int>& ring_begin)
    : points_(std::move(points)) {
  const int n = static_cast<int>(points_.size());
  runs_.reserve(n / kRunLength + ring_begin.size() + 1);
  size_t next_ring = 0;
  for (int begin = 0; begin < n;) {
    while (next_ring < ring_begin.size() && ring_begin[next_ring] <= begin) ++next_ring;
    const int ring_end = next_ring < ring_begin.size() ? ring_begin[next_ring] : n;
    const int end = std::min(begin + kRunLength, ring_end);
    Box box{points_[begin], points_[begin]};
    for (int k = begin + 1; k < end; ++k) {
      box.lower = box.lower.cwiseMin(points_[k]);
      box.upper = box.upper.cwiseMax(points_[k]);
    }
    runs_.push_back({box, begin, end});
    begin = end;
  }
  if (!runs_.empty()) {
    nodes_.reserve(2 * runs_.size() / kLeafRuns + 2);
    Build(0, static_cast<int>(runs_.size()));
  }
}

int PointTree::Build(int begin, int end) {
  const int node = static_cast<int>(nodes_.size());
  Box box = runs_[begin].box;
  for (int k = begin + 1; k < end; ++k) {
    box.lower = box.lower.cwiseMin(runs_[k].box.lower);
    box.upper = box.upper.cwiseMax(runs_[k].box.upper);
  }
  nodes_.push_back({box, begin, end});
  if (end - begin <= kLeafRuns) return node;
  // Split the wider side at the median of the runs' centres.
  const int axis = box.upper.x() - box.lower.x() >= box.upper.y() - box.lower.y() ? 0 : 1;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(runs_.begin() + begin, runs_.begin() + middle, runs_.begin() + end,
                   [axis](const Run& a, const Run& b) {
                     return a.box.lower[axis] + a.box.upper[axis] <
                            b.box.lower[axis] + b.box.upper[axis];
                   });
  const int left = Build(begin, middle);
  const int right = Build(middle, end);
  nodes_[node].left = left;
  nodes_[node].right = right;
  return node;
}

}  // namespace acdplan::acd::internal
