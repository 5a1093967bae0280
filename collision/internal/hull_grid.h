#pragma once
// A uniform grid over convex hulls given as half-spaces: the hull-based point location of
// dissertation Algorithm 8 without its loop over every hull. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace acdplan::collision::internal {

/// Point queries on a set of convex hulls. The hulls' common box is cut into about
/// `kTargetCells` cubic-ish cells; each cell is marked *covered* when one hull contains all of it,
/// and lists the hulls that may contain a point of it (those no single hull plane separates from
/// it). A point of a covered cell is answered by one lookup; otherwise only the listed hulls are
/// tested. Answers equal the plain test "n . p <= d + slack for every plane of some hull" except
/// within rounding of that boundary, where the grid errs towards inside (conservative).
/// Build O(sum over hulls of planes x cells in the hull's box); a query O(hulls listed in its
/// cell), O(1) in a covered or empty cell. Immutable after construction; queries are
/// thread-safe.
class HullGrid {
 public:
  HullGrid() = default;
  /// `planes[i]` (#H by 4 rows (n, d), unit n, hull i = {x : n . x <= d}) and `boxes[i]` its
  /// box. `slack` [units] >= 0 loosens every half-space and box so that rounding never puts a
  /// point of a hull outside it (the test is conservative).
  HullGrid(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
           const std::vector<Eigen::AlignedBox3d>& boxes, double slack);

  /// True if some hull contains `p`.
  bool AnyContains(const Eigen::Vector3d& p) const;

  /// Appends to `out` every hull that contains `p`, in increasing order.
  void Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const;

  int size() const { return static_cast<int>(hull_plane_begin_.size()) - 1; }

  /// Cells in the grid (about this many when there is at least one hull).
  static constexpr int kTargetCells = 1 << 16;

 private:
  bool HullContains(int hull, const Eigen::Vector3d& p) const;
  // The cell of `p`, or -1 outside the grid.
  int CellOf(const Eigen::Vector3d& p) const;

  std::vector<int> hull_plane_begin_{0};  // planes of hull i: [begin[i], begin[i + 1])
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>> planes_;  // d + slack
  Eigen::AlignedBox3d bounds_;  // the grid: the hulls' boxes, loosened by the slack
  Eigen::Vector3d cell_size_ = Eigen::Vector3d::Ones();
  Eigen::Vector3i cells_ = Eigen::Vector3i::Zero();  // per axis
  std::vector<std::uint8_t> covered_;                // per cell: one hull contains it all
  std::vector<int> cell_begin_;  // hulls listed for cell c: cell_hulls_[begin[c], begin[c + 1])
  std::vector<int> cell_hulls_;
};

}  // namespace acdplan::collision::internal
