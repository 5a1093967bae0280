#include "collision/internal/hull_grid.h"

#include <algorithm>
#include <cmath>

namespace acdplan::collision::internal {
namespace {

// The smallest and largest of n . x over the box [lo, hi].
double MinOver(const Eigen::Vector3d& n, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += n[k] * (n[k] >= 0 ? lo[k] : hi[k]);
  return s;
}
double MaxOver(const Eigen::Vector3d& n, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += n[k] * (n[k] >= 0 ? hi[k] : lo[k]);
  return s;
}

using Planes = std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>>;

/// A cell a hull reaches, with the planes of the hull that cross it: crossing[begin, end), indices
/// into the planes of every hull (HullGrid's constructor).
struct ReachedCell {
  int hull;
  int cell;
  int begin, end;  // into HullSorter::crossing
};

/// One hull being sorted into the cells.
struct HullSorter {
  const Planes& planes;  // every hull's planes, d + slack
  int hull;
  Eigen::AlignedBox3d box;
  double slack;
  Eigen::Vector3d origin, cell_size;  // of the cells inside the border
  Eigen::Vector3i dims;               // cells per axis, border included
  // The cells the hull reaches (padded indices) are appended; the planes of each are ranges of
  // `crossing`.
  std::vector<ReachedCell>* reached;
  std::vector<int>* crossing;
  // The planes that may cross the block being sorted, a stack of ranges (no allocation per
  // block: a 2D world's grid sorts tens of thousands of blocks).
  std::vector<int> stack;

  // Sorts the block of cells [lo, hi] (inclusive), given the planes stack[begin, end) that may
  // cross it. Cell boxes are grown by the slack, so that a point rounded into a neighbouring cell
  // still lies in the box its cell was sorted by. A plane with the whole block beyond it by
  // another slack excludes the block (the plain test says "outside" for all of it, even after
  // rounding); one with the whole block inside it by a slack holds for every point of it and is
  // dropped; the others cross the block, which is halved until it is one cell.
  void Sort(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi, size_t begin, size_t end) {
    const Eigen::Vector3d bmin =
        origin + lo.cast<double>().cwiseProduct(cell_size) - Eigen::Vector3d::Constant(slack);
    const Eigen::Vector3d bmax =
        origin + (hi + Eigen::Vector3i::Ones()).cast<double>().cwiseProduct(cell_size) +
        Eigen::Vector3d::Constant(slack);
    if (!Eigen::AlignedBox3d(bmin, bmax).intersects(box)) return;
    const size_t still = stack.size();
    for (size_t i = begin; i < end; ++i) {
      const int k = stack[i];
      const Eigen::Vector3d n = planes[static_cast<size_t>(k)].head<3>();
      const double d = planes[static_cast<size_t>(k)](3);
      if (MinOver(n, bmin, bmax) > d + slack) {
        stack.resize(still);
        return;
      }
      if (MaxOver(n, bmin, bmax) > d - slack) stack.push_back(k);
    }
    const size_t still_end = stack.size();
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    if (still == still_end || lo == hi) {
      const int first = static_cast<int>(crossing->size());
      crossing->insert(crossing->end(), stack.begin() + static_cast<std::ptrdiff_t>(still),
                       stack.end());
      const int last = static_cast<int>(crossing->size());
      for (int z = lo.z(); z <= hi.z(); ++z) {
        for (int y = lo.y(); y <= hi.y(); ++y) {
          for (int x = lo.x(); x <= hi.x(); ++x) {
            reached->push_back(
                {hull, ((z + 1) * dims.y() + y + 1) * dims.x() + x + 1, first, last});
          }
        }
      }
    } else {
      const int mid = (lo[axis] + hi[axis]) / 2;
      Eigen::Vector3i left_hi = hi, right_lo = lo;
      left_hi[axis] = mid;
      right_lo[axis] = mid + 1;
      Sort(lo, left_hi, still, still_end);
      Sort(right_lo, hi, still, still_end);
    }
    stack.resize(still);
  }
};

}  // namespace

Eigen::Vector3i HullGrid::CellsPerAxis(const Eigen::Vector3d& extent, const Eigen::Vector3i& fixed,
                                       int target_cells) {
  // Cubic cells of edge h, (extent / h) per axis and about target_cells in all, except on an
  // axis where that gives fewer than kMinCellsPerAxis: a flat set of hulls (a wall, a plaque)
  // would otherwise have a few layers of cells, nearly all crossed by its two large faces. Such
  // an axis gets kMinCellsPerAxis and the others share what is left, cubically again. An
  // extent of zero gets one cell.
  Eigen::Vector3i cells;  // 0: not set yet
  for (int k = 0; k < 3; ++k) cells[k] = fixed[k] > 0 ? fixed[k] : extent[k] > 0 ? 0 : 1;
  for (;;) {
    double budget = target_cells, free_volume = 1;
    int free_axes = 0;
    for (int k = 0; k < 3; ++k) {
      if (cells[k] > 0) {
        budget /= cells[k];
      } else {
        free_volume *= extent[k];
        ++free_axes;
      }
    }
    if (free_axes == 0) return cells;
    const double h = std::pow(free_volume / budget, 1.0 / free_axes);
    bool flat = false;
    for (int k = 0; k < 3; ++k) {
      if (cells[k] == 0 && extent[k] / h < kMinCellsPerAxis) {
        cells[k] = kMinCellsPerAxis;
        flat = true;
      }
    }
    if (flat) continue;
    for (int k = 0; k < 3; ++k) {
      if (cells[k] == 0) {
        cells[k] = std::clamp(static_cast<int>(std::ceil(extent[k] / h)), 1, target_cells);
      }
    }
    return cells;
  }
}

HullGrid::HullGrid(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
                   const std::vector<Eigen::AlignedBox3d>& boxes, double slack, bool prisms_in_z,
                   int target_cells)
    : hull_count_(static_cast<int>(planes.size())) {
  std::vector<Eigen::AlignedBox3d> loose = boxes;
  Eigen::AlignedBox3d bounds;
  for (auto& box : loose) {
    box.min().array() -= slack;
    box.max().array() += slack;
    bounds.extend(box);
  }
  if (loose.empty()) return;

  // Inside the border.
  const Eigen::Vector3i cells =
      CellsPerAxis(bounds.sizes(), {0, 0, prisms_in_z ? 3 : 0}, target_cells);
  const Eigen::Vector3d extent = bounds.sizes().cwiseMax(1e-300);
  for (int k = 0; k < 3; ++k) {
    cell_size_[k] = extent[k] / cells[k];
    inverse_cell_size_[k] = 1 / cell_size_[k];
  }
  origin_ = bounds.min() - cell_size_;
  dims_ = cells + Eigen::Vector3i::Constant(2);
  last_cell_ = (dims_ - Eigen::Vector3i::Ones()).cast<double>();
  // Every hull's loosened planes, one after the other, and the cells each hull reaches.
  Planes all_planes;
  std::vector<int> crossing;         // indices into all_planes
  std::vector<ReachedCell> reached;  // hull by hull
  for (size_t i = 0; i < loose.size(); ++i) {
    const int first_plane = static_cast<int>(all_planes.size());
    for (Eigen::Index r = 0; r < planes[i].rows(); ++r) {
      Eigen::Vector4d plane = planes[i].row(r).transpose();
      plane(3) += slack;
      all_planes.push_back(plane);
    }
    HullSorter sorter{
        all_planes, static_cast<int>(i), loose[i], slack, bounds.min(), cell_size_, dims_,
        &reached,   &crossing,           {}};
    for (int k = first_plane; k < static_cast<int>(all_planes.size()); ++k) {
      sorter.stack.push_back(k);
    }
    sorter.Sort(Eigen::Vector3i::Zero(), cells - Eigen::Vector3i::Ones(), 0, sorter.stack.size());
  }
  const size_t padded_count = static_cast<size_t>(dims_.prod());
  std::vector<std::uint8_t> covered(padded_count, 0);  // inside a hull with planes
  for (const ReachedCell& c : reached) {
    if (c.begin == c.end && planes[static_cast<size_t>(c.hull)].rows() > 0) {
      covered[static_cast<size_t>(c.cell)] = 1;
    }
  }

  // The entries by cell (a counting sort, hulls in increasing order within a cell), each with
  // its crossing planes copied next to each other.
  cell_begin_.assign(padded_count + 1, 0);
  for (const ReachedCell& c : reached) ++cell_begin_[static_cast<size_t>(c.cell) + 1];
  for (size_t c = 0; c < padded_count; ++c) cell_begin_[c + 1] += cell_begin_[c];
  std::vector<int> next(cell_begin_.begin(), cell_begin_.end() - 1);
  entries_.resize(reached.size());
  for (const ReachedCell& c : reached) {
    entries_[static_cast<size_t>(next[static_cast<size_t>(c.cell)]++)] = {c.hull, c.begin, c.end};
  }
  cell_planes_.reserve(crossing.size());
  for (Entry& entry : entries_) {
    const int begin = static_cast<int>(cell_planes_.size());
    for (int j = entry.plane_begin; j < entry.plane_end; ++j) {
      cell_planes_.push_back(all_planes[static_cast<size_t>(crossing[static_cast<size_t>(j)])]);
    }
    entry.plane_begin = begin;
    entry.plane_end = static_cast<int>(cell_planes_.size());
  }
  kinds_.assign((padded_count + 31) / 32, 0);
  for (size_t c = 0; c < padded_count; ++c) {
    const Kind kind = covered[c] ? kCovered : cell_begin_[c + 1] > cell_begin_[c] ? kMixed : kEmpty;
    kinds_[c >> 5] |= static_cast<std::uint64_t>(kind) << (2 * (c & 31));
  }
  // The subcells of the mixed cells, their boxes grown by the slack as the cells' were in
  // HullSorter::Sort.
  mixed_before_.reserve(kinds_.size());
  int mixed = 0;
  for (const std::uint64_t word : kinds_) {
    mixed_before_.push_back(mixed);
    mixed += BitCount(word & kMixedBits);
  }
  mixed_subcells_.reserve(static_cast<size_t>(mixed));
  const size_t layer = static_cast<size_t>(dims_.x() * dims_.y());
  for (size_t padded = 0; padded < padded_count; ++padded) {
    if (KindOf(static_cast<int>(padded)) != kMixed) continue;
    if (prisms_in_z && padded / layer != 2) {
      // A 2D world's points are at mid-height, in the middle layer (padded z = 2): the caps'
      // layers are never queried, and their subcells are left mixed (the plane test, as exact)
      // rather than classified. Most mixed cells of a 2D world are there, under every prism.
      SubcellKinds& all_mixed = mixed_subcells_.emplace_back();
      all_mixed.words[0] = all_mixed.words[1] = kMixedBits;
      continue;
    }
    const Eigen::Vector3d corner =
        origin_ +
        Eigen::Vector3i(static_cast<int>(padded % static_cast<size_t>(dims_.x())),
                        static_cast<int>(padded / static_cast<size_t>(dims_.x()) %
                                         static_cast<size_t>(dims_.y())),
                        static_cast<int>(padded / static_cast<size_t>(dims_.x() * dims_.y())))
            .cast<double>()
            .cwiseProduct(cell_size_);
    ClassifySubcells(static_cast<int>(padded), corner, slack, Eigen::Vector3i::Zero(), kSubcells,
                     &mixed_subcells_.emplace_back());
  }
}

void HullGrid::ClassifySubcells(int cell, const Eigen::Vector3d& corner, double slack,
                                const Eigen::Vector3i& at, int size, SubcellKinds* kinds) const {
  // A block that is empty or covered as a whole is so in every subcell of it (ClassifyBox of a
  // smaller box: no plane excludes less, none holds on less), so only mixed blocks are halved:
  // the same kinds as classifying the 64 subcells one by one, for a fraction of the tests.
  const Eigen::Vector3d sub_size = cell_size_ / kSubcells;
  const Eigen::Vector3d lo =
      corner + at.cast<double>().cwiseProduct(sub_size) - Eigen::Vector3d::Constant(slack);
  const Eigen::Vector3d hi =
      corner + (at + Eigen::Vector3i::Constant(size)).cast<double>().cwiseProduct(sub_size) +
      Eigen::Vector3d::Constant(slack);
  const Kind kind = ClassifyBox(cell, lo, hi, slack);
  if (kind == kMixed && size > 1) {
    const int half = size / 2;
    for (int octant = 0; octant < 8; ++octant) {
      const Eigen::Vector3i offset(octant & 1, (octant >> 1) & 1, (octant >> 2) & 1);
      ClassifySubcells(cell, corner, slack, at + half * offset, half, kinds);
    }
    return;
  }
  for (int z = at.z(); z < at.z() + size; ++z) {
    for (int y = at.y(); y < at.y() + size; ++y) {
      for (int x = at.x(); x < at.x() + size; ++x) {
        const int s = (z * kSubcells + y) * kSubcells + x;
        kinds->words[s >> 5] |= static_cast<std::uint64_t>(kind) << (2 * (s & 31));
      }
    }
  }
}

HullGrid::Kind HullGrid::ClassifyBox(int cell, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                     double slack) const {
  // As HullSorter::Sort: a plane (d + slack) with the whole box beyond it by another slack
  // excludes its hull; one that holds on all of the box by a slack drops out.
  bool reached = false;
  for (int e = cell_begin_[static_cast<size_t>(cell)];
       e < cell_begin_[static_cast<size_t>(cell) + 1]; ++e) {
    const Entry& entry = entries_[static_cast<size_t>(e)];
    bool excluded = false, holds = true;
    for (int k = entry.plane_begin; k < entry.plane_end && !excluded; ++k) {
      const Eigen::Vector3d n = cell_planes_[static_cast<size_t>(k)].head<3>();
      const double d = cell_planes_[static_cast<size_t>(k)](3);
      excluded = MinOver(n, lo, hi) > d + slack;
      holds = holds && MaxOver(n, lo, hi) <= d - slack;
    }
    if (excluded) continue;
    if (holds) return kCovered;
    reached = true;
  }
  return reached ? kMixed : kEmpty;
}

bool HullGrid::EntryContains(const Entry& entry, const Eigen::Vector3d& p) const {
  const Eigen::Vector4d q(p.x(), p.y(), p.z(), -1.0);
  for (int k = entry.plane_begin; k < entry.plane_end; ++k) {
    if (cell_planes_[static_cast<size_t>(k)].dot(q) > 0) return false;
  }
  return true;
}

bool HullGrid::PlanesContain(int cell, const Eigen::Vector3d& p) const {
  const size_t c = static_cast<size_t>(cell);
  for (int k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
    if (EntryContains(entries_[static_cast<size_t>(k)], p)) return true;
  }
  return false;
}

void HullGrid::Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const {
  const Location at = Locate(p);
  const Kind kind = KindOf(at.cell);
  if (kind == kEmpty || (kind == kMixed && SubcellKindOf(at) == kEmpty)) return;
  const size_t c = static_cast<size_t>(at.cell);
  for (int k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
    const Entry& entry = entries_[static_cast<size_t>(k)];
    if (EntryContains(entry, p)) out->push_back(entry.hull);
  }
}

}  // namespace acdplan::collision::internal
