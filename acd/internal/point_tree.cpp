#include "acd/internal/point_tree.h"

#include <algorithm>

namespace acdplan::acd::internal {
namespace {

constexpr int kLeafSize = 16;

}  // namespace

PointTree::PointTree(const std::vector<Point2d>& points) {
  const int n = static_cast<int>(points.size());
  entries_.reserve(n);
  for (int i = 0; i < n; ++i) entries_.push_back({points[i], i});
  if (n > 0) {
    nodes_.reserve(2 * n / kLeafSize + 2);
    Build(0, n);
  }
}

int PointTree::Build(int begin, int end) {
  const int node = static_cast<int>(nodes_.size());
  Point2d lower = entries_[begin].point, upper = lower;
  for (int k = begin + 1; k < end; ++k) {
    lower = lower.cwiseMin(entries_[k].point);
    upper = upper.cwiseMax(entries_[k].point);
  }
  nodes_.push_back({lower, upper, begin, end});
  if (end - begin <= kLeafSize) return node;
  // Split the wider side at the median.
  const int axis = upper.x() - lower.x() >= upper.y() - lower.y() ? 0 : 1;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(
      entries_.begin() + begin, entries_.begin() + middle, entries_.begin() + end,
      [axis](const Entry& a, const Entry& b) { return a.point[axis] < b.point[axis]; });
  const int left = Build(begin, middle);
  const int right = Build(middle, end);
  nodes_[node].left = left;
  nodes_[node].right = right;
  return node;
}

}  // namespace acdplan::acd::internal
