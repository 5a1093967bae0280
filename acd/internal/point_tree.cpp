#include "acd/internal/point_tree.h"

#include <algorithm>
#include <numeric>

namespace acdplan::acd::internal {
namespace {

constexpr int kLeafSize = 8;

}  // namespace

PointTree::PointTree(const std::vector<Point2d>& points) : points_(points), order_(points.size()) {
  std::iota(order_.begin(), order_.end(), 0);
  if (!points_.empty()) {
    nodes_.reserve(2 * points_.size() / kLeafSize + 2);
    Build(0, static_cast<int>(points_.size()));
  }
}

int PointTree::Build(int begin, int end) {
  const int node = static_cast<int>(nodes_.size());
  Point2d lower = points_[order_[begin]], upper = lower;
  for (int k = begin + 1; k < end; ++k) {
    lower = lower.cwiseMin(points_[order_[k]]);
    upper = upper.cwiseMax(points_[order_[k]]);
  }
  nodes_.push_back({lower, upper, begin, end});
  if (end - begin <= kLeafSize) return node;
  // Split the wider side at the median.
  const int axis = upper.x() - lower.x() >= upper.y() - lower.y() ? 0 : 1;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
  const int left = Build(begin, middle);
  const int right = Build(middle, end);
  nodes_[node].left = left;
  nodes_[node].right = right;
  return node;
}

}  // namespace acdplan::acd::internal
