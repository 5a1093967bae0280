#pragma once
// A uniform grid over convex hulls given as half-spaces: the hull-based point location of
// dissertation Algorithm 8 without its loop over every hull. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace acdplan::collision::internal {

/// Point queries on a set of convex hulls. The hulls' common box is cut into about
/// `kTargetCells` near-cubic cells; each cell lists the hulls that may contain a point of it (no
/// plane of theirs has the whole cell outside), each with only the planes that cross the cell
/// (the others hold on all of it). A cell inside one hull is *covered* and a cell no hull reaches
/// is *empty*: one lookup in a 2-bit-per-cell array (16 KiB, so it stays in the L1 cache under
/// random queries) answers their points; elsewhere a query tests a few planes of a few hulls. The
/// answers equal the plain test "n . p <= d + slack for every plane of some hull", up to rounding
/// at that boundary. Build O(planes x cells met by each hull's surface), by halving blocks of cells
/// that a plane crosses; a query O(listed planes of its cell). Immutable after construction;
/// queries are thread-safe.
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

  int size() const { return hull_count_; }

  /// Cells in the grid (about this many when there is at least one hull).
  static constexpr int kTargetCells = 1 << 16;

 private:
  /// A hull listed in a cell, with the planes of it that cross the cell.
  struct Entry {
    int hull = 0;
    int plane_begin = 0, plane_end = 0;  // into cell_planes_
  };
  /// What a cell holds, 2 bits per cell in kinds_.
  enum Kind : std::uint8_t { kEmpty = 0, kCovered = 1, kMixed = 2 };
  // The cell of `p`, or -1 outside the grid.
  int CellOf(const Eigen::Vector3d& p) const;
  Kind KindOf(int cell) const {
    return static_cast<Kind>((kinds_[static_cast<size_t>(cell) >> 2] >> (2 * (cell & 3))) & 3);
  }
  bool EntryContains(const Entry& entry, const Eigen::Vector3d& p) const;

  int hull_count_ = 0;
  Eigen::AlignedBox3d bounds_;  // the grid: the hulls' boxes, loosened by the slack
  Eigen::Vector3d cell_size_ = Eigen::Vector3d::Ones();
  Eigen::Vector3d inverse_cell_size_ = Eigen::Vector3d::Ones();
  Eigen::Vector3i cells_ = Eigen::Vector3i::Zero();  // per axis
  std::vector<std::uint8_t> kinds_;                  // a Kind per cell, four cells a byte
  std::vector<int> cell_begin_;  // entries of cell c: entries_[begin[c], begin[c + 1])
  std::vector<Entry> entries_;
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>>
      cell_planes_;  // d + slack
};

}  // namespace acdplan::collision::internal
