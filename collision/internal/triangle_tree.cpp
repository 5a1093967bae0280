#include "collision/internal/triangle_tree.h"

#include <algorithm>
#include <numeric>

namespace acdplan::collision::internal {

TriangleTree::TriangleTree(std::vector<Triangle3> triangles) : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  boxes_.reserve(triangles_.size());
  for (const Triangle3& t : triangles_) {
    Eigen::AlignedBox3d box(t[0]);
    box.extend(t[1]).extend(t[2]);
    boxes_.push_back(box);
  }
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 1);
  Build();
}

void TriangleTree::Build() {
  // Each task fills one node for the triangles order[begin, end), partitioning that range at its
  // median centroid; a split node's two children are appended together, so they sit at first and
  // first + 1. The triangles take the final order once, at the end.
  struct Task {
    int node, begin, end;
  };
  std::vector<int> order(triangles_.size());
  std::iota(order.begin(), order.end(), 0);
  nodes_.emplace_back();
  std::vector<Task> tasks = {{0, 0, static_cast<int>(triangles_.size())}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    Node& node = nodes_[static_cast<size_t>(task.node)];
    for (int i = task.begin; i < task.end; ++i) {
      node.box.extend(boxes_[static_cast<size_t>(order[static_cast<size_t>(i)])]);
    }
    if (task.end - task.begin <= kLeafSize) {
      node.first = task.begin;
      node.count = task.end - task.begin;
      continue;
    }
    int axis = 0;
    node.box.sizes().maxCoeff(&axis);
    auto center = [&](int i) { return boxes_[static_cast<size_t>(i)].center()[axis]; };
    const int mid = task.begin + (task.end - task.begin) / 2;
    // Ties by index: the same tree with any standard library.
    std::nth_element(
        order.begin() + task.begin, order.begin() + mid, order.begin() + task.end,
        [&](int a, int b) { return center(a) < center(b) || (center(a) == center(b) && a < b); });
    const int children = static_cast<int>(nodes_.size());
    node.first = children;  // before emplace_back, which may move `node`
    nodes_.emplace_back();
    nodes_.emplace_back();
    tasks.push_back({children, task.begin, mid});
    tasks.push_back({children + 1, mid, task.end});
  }
  std::vector<Triangle3> triangles;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const int i : order) {
    triangles.push_back(triangles_[static_cast<size_t>(i)]);
    boxes.push_back(boxes_[static_cast<size_t>(i)]);
  }
  triangles_ = std::move(triangles);
  boxes_ = std::move(boxes);
}

}  // namespace acdplan::collision::internal
