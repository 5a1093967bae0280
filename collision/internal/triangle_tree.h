#pragma once
// A static tree of bounding boxes over triangles: the triangles near a box, for the exact
// confirmation of a hull hit by a convex robot (CollisionMode::kHullsExact). Internal.

#include <Eigen/Geometry>
#include <vector>

#include "collision/internal/convex_separation.h"

namespace acdplan::collision::internal {

/// Triangles in a binary tree of axis-aligned boxes (split at the median centroid of the longest
/// axis, up to kLeafSize triangles a leaf): a box query visits O(log n + k) nodes for k triangles
/// whose boxes meet it, whatever the triangles' sizes. Immutable after construction; queries are
/// thread-safe.
class TriangleTree {
 public:
  TriangleTree() = default;
  explicit TriangleTree(std::vector<Triangle3> triangles);

  /// True if `test(t)` is true for a triangle t whose box meets `box` (boxes that touch meet);
  /// stops at the first. Each such triangle is tested at most once.
  template <class Test>
  bool AnyNear(const Eigen::AlignedBox3d& box, Test&& test) const {
    if (nodes_.empty()) return false;
    int stack[kMaxDepth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<size_t>(stack[--top])];
      if (!node.box.intersects(box)) continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) {
          if (boxes_[static_cast<size_t>(i)].intersects(box) &&
              test(triangles_[static_cast<size_t>(i)])) {
            return true;
          }
        }
      } else {
        stack[top++] = node.first;  // the children are nodes first and first + 1
        stack[top++] = node.first + 1;
      }
    }
    return false;
  }

  size_t size() const { return triangles_.size(); }

  static constexpr int kLeafSize = 4;

 private:
  /// A leaf (count > 0) holds triangles [first, first + count); an inner node (count 0) has its
  /// children at nodes first and first + 1.
  struct Node {
    Eigen::AlignedBox3d box;
    int first = 0, count = 0;
  };
  // Halving n triangles kLeafSize at a time takes log2(n / kLeafSize) levels; the stack holds at
  // most one pending node per level plus one.
  static constexpr int kMaxDepth = 64;

  void Build();

  std::vector<Triangle3> triangles_;
  std::vector<Eigen::AlignedBox3d> boxes_;  // of triangles_[i]
  std::vector<Node> nodes_;
};

}  // namespace acdplan::collision::internal
