#pragma once
// A uniform grid over convex hulls given as half-spaces: the hull-based point location of
// dissertation Algorithm 8 without its loop over every hull. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <vector>

namespace acdplan::collision::internal {

/// Point queries on a set of convex hulls. The hulls' common box is cut into about
/// `target_cells` near-cubic cells (flattened on a thin axis, CellsPerAxis()); each cell lists the
/// hulls that may contain a point of it (no plane of theirs has the whole cell outside), each with
/// only the planes that cross the cell (the others hold on all of it). A cell inside one hull is
/// *covered* and a cell no hull reaches is *empty*: one lookup in a 2-bit-per-cell array (about 18
/// KiB with the grid's border at kTargetCells, 70 KiB at kFineCells: read from the L1 and L2
/// caches under random queries) answers their points. The other, *mixed* cells (where hull surfaces
/// pass) are cut again into 4 x 4 x 4 subcells, each empty, covered or mixed in a 128-bit mask, so
/// that most of their points are answered without a plane test too; only a point of a mixed subcell
/// tests a few planes of a few hulls. The answers equal the plain test "n . p <= d + slack for
/// every plane of some hull", up to rounding at that boundary. Build O(planes x cells met by each
/// hull's surface), by halving blocks of cells that a plane crosses; a query O(listed planes of its
/// cell). Immutable after construction; queries are thread-safe.
class HullGrid {
 public:
  HullGrid() = default;
  /// `planes[i]` (#H by 4 rows (n, d), unit n, hull i = {x : n . x <= d}) and `boxes[i]` its
  /// box. `slack` [units] >= 0 loosens every half-space and box so that rounding never puts a
  /// point of a hull outside it (the test is conservative). `prisms_in_z`: the hulls are prisms
  /// along z queried at mid-height (a 2D world's): three layers of cells in z, so that the middle
  /// one, where the queries fall, is clear of the caps, and the other cells go to x and y; the
  /// caps' layers keep their mixed cells' subcells unclassified (a point there, which a 2D world
  /// never asks for, gets the exact plane test). `target_cells`: about how many cells (kTargetCells
  /// or kFineCells).
  HullGrid(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
           const std::vector<Eigen::AlignedBox3d>& boxes, double slack, bool prisms_in_z = false,
           int target_cells = kTargetCells);

  /// True if some hull contains `p`. Inline: most points are answered by one lookup.
  bool AnyContains(const Eigen::Vector3d& p) const {
    const Location at = Locate(p);
    const Kind kind = KindOf(at.cell);
    if (kind != kMixed) return kind == kCovered;
    const Kind sub = SubcellKindOf(at);
    return sub == kMixed ? PlanesContain(at.cell, p) : sub == kCovered;
  }

  /// Appends to `out` every hull that contains `p`, in increasing order.
  void Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const;

  int size() const { return hull_count_; }

  /// Cells in a grid by default (about this many when there is at least one hull).
  static constexpr int kTargetCells = 1 << 16;
  /// Cells in a grid made for point location alone (PointLocator): finer cells leave fewer points
  /// to the mixed cells' slower path. On V-HACD's defsphere (29 hulls) 2^18 cells answered about
  /// 10% more random points per second than 2^16, and took 2.7 times as long to build (133 against
  /// 49 ms): too slow for the grid every CollisionWorld builds.
  static constexpr int kFineCells = 1 << 18;
  /// Fewest cells on an axis of positive extent (CellsPerAxis()).
  static constexpr int kMinCellsPerAxis = 16;
  /// Cells per axis for a box of `extent` (border excluded), about `target_cells` in all: see the
  /// definition. An axis whose `fixed` entry is positive gets that many.
  static Eigen::Vector3i CellsPerAxis(const Eigen::Vector3d& extent, const Eigen::Vector3i& fixed,
                                      int target_cells = kTargetCells);

 private:
  /// A hull listed in a cell, with the planes of it that cross the cell.
  struct Entry {
    int hull = 0;
    int plane_begin = 0, plane_end = 0;  // into cell_planes_
  };
  /// What a cell or a subcell holds, 2 bits each.
  enum Kind : std::uint8_t { kEmpty = 0, kCovered = 1, kMixed = 2 };
  /// Subcells per axis of a cell; 4^3 of them, 2 bits each, fill a SubcellKinds.
  static constexpr int kSubcells = 4;
  /// The kinds of a cell's subcells: subcell s at bits 2 (s mod 32) of word s / 32, with
  /// s = (z kSubcells + y) kSubcells + x (all empty in an empty cell, all covered in a covered
  /// one).
  struct SubcellKinds {
    std::uint64_t words[2] = {0, 0};
  };
  /// Where a point lies: its cell, and its coordinates in cell units (for its subcell, found
  /// only when needed).
  struct Location {
    int cell = 0;
    double scaled[3] = {0, 0, 0};
  };
  // Without a branch on where `p` is (the bench's points fall inside and outside the grid at
  // random): a point outside the hulls' box clamps into the grid's border of empty cells, and
  // so does NaN (std::min and std::max return their first argument then).
  Location Locate(const Eigen::Vector3d& p) const {
    Location at;
    for (int k = 2; k >= 0; --k) {
      at.scaled[k] = (p[k] - origin_[k]) * inverse_cell_size_[k];
      const int i = static_cast<int>(std::max(0.0, std::min(at.scaled[k], last_cell_[k])));
      at.cell = at.cell * dims_[k] + i;
    }
    return at;
  }
  // The subcell of `at`, asked only of cells some hull reaches (inside the border, scaled >= 1).
  static int SubcellOf(const Location& at) {
    int s = 0;
    for (int k = 2; k >= 0; --k) {
      const double fraction = at.scaled[k] - static_cast<int>(at.scaled[k]);
      s = s * kSubcells + std::clamp(static_cast<int>(fraction * kSubcells), 0, kSubcells - 1);
    }
    return s;
  }
  // The set bits of `x`. Bit arithmetic rather than __builtin_popcountll: the library is built
  // for the baseline x86-64, without the popcnt instruction, where the builtin is a call.
  static int BitCount(std::uint64_t x) {
    x -= (x >> 1) & 0x5555555555555555u;
    x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
    x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Fu;
    return static_cast<int>((x * 0x0101010101010101u) >> 56);
  }
  // Whether a hull listed in `cell` contains `p`, by its planes that cross the cell.
  bool PlanesContain(int cell, const Eigen::Vector3d& p) const;
  Kind KindOf(int cell) const {
    return static_cast<Kind>((kinds_[static_cast<size_t>(cell) >> 5] >> (2 * (cell & 31))) & 3);
  }
  // The subcell kind of `at`, in a mixed cell. Mixed cells are numbered in cell order: the
  // mixed cells before `at.cell` are those of the earlier words of kinds_ plus the mixed bits
  // (the high bit of a cell's two) below it in its own word.
  Kind SubcellKindOf(const Location& at) const {
    const size_t c = static_cast<size_t>(at.cell);
    const std::uint64_t below = (std::uint64_t{1} << (2 * (c & 31))) - 1;
    const size_t mixed_index =
        mixed_before_[c >> 5] + static_cast<size_t>(BitCount(kinds_[c >> 5] & below & kMixedBits));
    const int s = SubcellOf(at);
    return static_cast<Kind>((mixed_subcells_[mixed_index].words[s >> 5] >> (2 * (s & 31))) & 3);
  }
  // Sets the kinds of the size^3 subcells of mixed cell `cell` (lowest corner `corner`) from
  // subcell `at` on.
  void ClassifySubcells(int cell, const Eigen::Vector3d& corner, double slack,
                        const Eigen::Vector3i& at, int size, SubcellKinds* kinds) const;
  // The kind of the box [lo, hi] (already grown by `slack`) for the hulls of cell `cell`.
  Kind ClassifyBox(int cell, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                   double slack) const;
  bool EntryContains(const Entry& entry, const Eigen::Vector3d& p) const;

  int hull_count_ = 0;
  // The grid: the hulls' boxes (loosened by the slack) cut into cells, plus one border layer of
  // empty cells around them. With no hull it is one empty cell.
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // the border's lowest corner
  Eigen::Vector3d cell_size_ = Eigen::Vector3d::Ones();
  Eigen::Vector3d inverse_cell_size_ = Eigen::Vector3d::Ones();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();       // cells per axis, border included
  Eigen::Vector3d last_cell_ = Eigen::Vector3d::Zero();  // dims_ - 1
  // A Kind per cell, 32 cells a word: small enough for the fast caches under random queries.
  std::vector<std::uint64_t> kinds_ = std::vector<std::uint64_t>(1, 0);
  static constexpr std::uint64_t kMixedBits = 0xAAAAAAAAAAAAAAAAu;  // the kMixed bit of each
  std::vector<int> mixed_before_;  // per word of kinds_: the mixed cells in earlier words
  // The subcells of the mixed cells only, in cell order (a few hundred KiB: a point of a mixed
  // cell reads one entry, mostly from the L2 cache).
  std::vector<SubcellKinds> mixed_subcells_;
  std::vector<int> cell_begin_;  // entries of cell c: entries_[begin[c], begin[c + 1])
  std::vector<Entry> entries_;
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>>
      cell_planes_;  // d + slack
};

}  // namespace acdplan::collision::internal
