#pragma once
// A static bounding-volume hierarchy over convex hulls given as half-spaces: the hull-based
// point location of dissertation Algorithm 8 without its loop over every hull. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace acdplan::collision::internal {

/// A binary AABB tree (median split on the longest axis of the box centres, leaves of up to 4
/// hulls), stored flat in depth-first order with the hulls' half-spaces packed contiguously.
/// Build O(n log^2 n); a query visits the boxes that contain the point.
class HullTree {
 public:
  HullTree() = default;
  /// `planes[i]` (#H by 4 rows (n, d), hull i = {x : n . x <= d}) and `boxes[i]` its box.
  /// `slack` [units] >= 0 loosens every half-space and box so that rounding never puts a point
  /// of a hull outside it (the test is conservative).
  HullTree(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
           const std::vector<Eigen::AlignedBox3d>& boxes, double slack);

  /// True if some hull contains `p`.
  bool AnyContains(const Eigen::Vector3d& p) const;

  /// Appends to `out` every hull that contains `p`.
  void Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const;

  int size() const { return static_cast<int>(hull_plane_begin_.size()) - 1; }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int first = 0;  // leaf: first hull in order_; inner: right child index
    int count = 0;  // leaf: number of hulls; inner: 0
  };
  int Build(std::vector<int>& ids, int begin, int end,
            const std::vector<Eigen::AlignedBox3d>& boxes);
  bool HullContains(int hull, const Eigen::Vector3d& p) const;
  // Calls visit(hull) for each hull containing p until it returns true; returns that.
  template <class F>
  bool Visit(const Eigen::Vector3d& p, F&& visit) const;

  std::vector<Node> nodes_;
  std::vector<int> order_;                // hull ids in leaf order
  std::vector<int> hull_plane_begin_{0};  // planes of hull i: [begin[i], begin[i + 1])
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>> planes_;
};

}  // namespace acdplan::collision::internal
