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
  // Each task fills one node for the triangles [begin, end), reordering them; a split node's two
  // children are appended together, so they sit at first and first + 1.
  struct Task {
    int node, begin, end;
  };
  nodes_.emplace_back();
  std::vector<Task> tasks = {{0, 0, static_cast<int>(triangles_.size())}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    Eigen::AlignedBox3d box;
    for (int i = task.begin; i < task.end; ++i) box.extend(boxes_[static_cast<size_t>(i)]);
    nodes_[static_cast<size_t>(task.node)].box = box;
    if (task.end - task.begin <= kLeafSize) {
      nodes_[static_cast<size_t>(task.node)].first = task.begin;
      nodes_[static_cast<size_t>(task.node)].count = task.end - task.begin;
      continue;
    }
    int axis = 0;
    box.sizes().maxCoeff(&axis);
    // Sort the index range by centroid on the axis (ties by index: the same tree everywhere),
    // then permute the triangles and their boxes.
    std::vector<int> order(static_cast<size_t>(task.end - task.begin));
    std::iota(order.begin(), order.end(), task.begin);
    const int mid = task.begin + (task.end - task.begin) / 2;
    auto center = [&](int i) { return boxes_[static_cast<size_t>(i)].center()[axis]; };
    std::nth_element(
        order.begin(), order.begin() + (mid - task.begin), order.end(),
        [&](int a, int b) { return center(a) < center(b) || (center(a) == center(b) && a < b); });
    std::vector<Triangle3> t;
    std::vector<Eigen::AlignedBox3d> b;
    for (const int i : order) {
      t.push_back(triangles_[static_cast<size_t>(i)]);
      b.push_back(boxes_[static_cast<size_t>(i)]);
    }
    std::copy(t.begin(), t.end(), triangles_.begin() + task.begin);
    std::copy(b.begin(), b.end(), boxes_.begin() + task.begin);
    const int children = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[static_cast<size_t>(task.node)].first = children;
    tasks.push_back({children, task.begin, mid});
    tasks.push_back({children + 1, mid, task.end});
  }
}

}  // namespace acdplan::collision::internal
