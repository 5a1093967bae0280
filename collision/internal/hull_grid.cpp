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

/// One hull being sorted into the cells.
struct HullSorter {
  const Planes& planes;  // the hull's planes, d + slack
  Eigen::AlignedBox3d box;
  double slack;
  Eigen::Vector3d origin, cell_size;
  Eigen::Vector3i cells;
  // Per cell: the planes (indices into `planes`) that cross it, for the cells the hull reaches.
  std::vector<std::pair<int, std::vector<int>>>* reached;

  // Sorts the block of cells [lo, hi] (inclusive), given the planes that may cross it. Cell
  // boxes are grown by the slack, so that a point rounded into a neighbouring cell still lies in
  // the box its cell was sorted by. A plane with the whole block beyond it by another slack
  // excludes the block (the plain test says "outside" for all of it, even after rounding); one
  // with the whole block inside it by a slack holds for every point of it and is dropped; the
  // others cross the block, which is halved until it is one cell.
  void Sort(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi,
            const std::vector<int>& crossing) {
    const Eigen::Vector3d bmin =
        origin + lo.cast<double>().cwiseProduct(cell_size) - Eigen::Vector3d::Constant(slack);
    const Eigen::Vector3d bmax =
        origin + (hi + Eigen::Vector3i::Ones()).cast<double>().cwiseProduct(cell_size) +
        Eigen::Vector3d::Constant(slack);
    if (!Eigen::AlignedBox3d(bmin, bmax).intersects(box)) return;
    std::vector<int> still;
    for (const int k : crossing) {
      const Eigen::Vector3d n = planes[static_cast<size_t>(k)].head<3>();
      const double d = planes[static_cast<size_t>(k)](3);
      if (MinOver(n, bmin, bmax) > d + slack) return;
      if (MaxOver(n, bmin, bmax) > d - slack) still.push_back(k);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    if (still.empty() || lo == hi) {
      for (int z = lo.z(); z <= hi.z(); ++z) {
        for (int y = lo.y(); y <= hi.y(); ++y) {
          for (int x = lo.x(); x <= hi.x(); ++x) {
            reached->emplace_back((z * cells.y() + y) * cells.x() + x, still);
          }
        }
      }
      return;
    }
    const int mid = (lo[axis] + hi[axis]) / 2;
    Eigen::Vector3i left_hi = hi, right_lo = lo;
    left_hi[axis] = mid;
    right_lo[axis] = mid + 1;
    Sort(lo, left_hi, still);
    Sort(right_lo, hi, still);
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
  const size_t cell_count = static_cast<size_t>(cells.prod());
  std::vector<std::uint8_t> covered(cell_count, 0);
  std::vector<std::vector<Entry>> lists(cell_count);
  std::vector<Planes> list_planes(cell_count);

  for (size_t i = 0; i < loose.size(); ++i) {
    Planes hull;
    for (Eigen::Index r = 0; r < planes[i].rows(); ++r) {
      Eigen::Vector4d plane = planes[i].row(r).transpose();
      plane(3) += slack;
      hull.push_back(plane);
    }
    std::vector<std::pair<int, std::vector<int>>> reached;
    HullSorter sorter{hull, loose[i], slack, bounds.min(), cell_size_, cells, &reached};
    std::vector<int> all(hull.size());
    for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    sorter.Sort(Eigen::Vector3i::Zero(), cells - Eigen::Vector3i::Ones(), all);
    for (const auto& [c, crossing] : reached) {
      Planes& to = list_planes[static_cast<size_t>(c)];
      Entry entry{static_cast<int>(i), static_cast<int>(to.size()), 0};
      for (const int k : crossing) to.push_back(hull[static_cast<size_t>(k)]);
      entry.plane_end = static_cast<int>(to.size());
      lists[static_cast<size_t>(c)].push_back(entry);
      if (crossing.empty() && !hull.empty()) covered[static_cast<size_t>(c)] = 1;
    }
  }

  // The padded grid: cell (x, y, z) inside the border is (x + 1, y + 1, z + 1).
  const size_t padded_count = static_cast<size_t>(dims_.prod());
  std::vector<size_t> inner_of(padded_count, cell_count);  // cell_count: a border cell
  for (size_t c = 0; c < cell_count; ++c) {
    const size_t x = c % static_cast<size_t>(cells.x());
    const size_t y = c / static_cast<size_t>(cells.x()) % static_cast<size_t>(cells.y());
    const size_t z = c / static_cast<size_t>(cells.x() * cells.y());
    inner_of[((z + 1) * static_cast<size_t>(dims_.y()) + y + 1) * static_cast<size_t>(dims_.x()) +
             x + 1] = c;
  }
  kinds_.assign((padded_count + 31) / 32, 0);
  cell_begin_.reserve(padded_count + 1);
  cell_begin_.push_back(0);
  for (size_t padded = 0; padded < padded_count; ++padded) {
    const size_t c = inner_of[padded];
    if (c < cell_count) {
      const Kind kind = covered[c] ? kCovered : lists[c].empty() ? kEmpty : kMixed;
      kinds_[padded >> 5] |= static_cast<std::uint64_t>(kind) << (2 * (padded & 31));
      const int offset = static_cast<int>(cell_planes_.size());
      for (Entry entry : lists[c]) {
        entry.plane_begin += offset;
        entry.plane_end += offset;
        entries_.push_back(entry);
      }
      cell_planes_.insert(cell_planes_.end(), list_planes[c].begin(), list_planes[c].end());
    }
    cell_begin_.push_back(static_cast<int>(entries_.size()));
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
  const Eigen::Vector3d sub_size = cell_size_ / kSubcells;
  for (size_t padded = 0; padded < padded_count; ++padded) {
    if (KindOf(static_cast<int>(padded)) != kMixed) continue;
    SubcellKinds& sub_kinds = mixed_subcells_.emplace_back();
    const Eigen::Vector3d corner =
        origin_ +
        Eigen::Vector3i(static_cast<int>(padded % static_cast<size_t>(dims_.x())),
                        static_cast<int>(padded / static_cast<size_t>(dims_.x()) %
                                         static_cast<size_t>(dims_.y())),
                        static_cast<int>(padded / static_cast<size_t>(dims_.x() * dims_.y())))
            .cast<double>()
            .cwiseProduct(cell_size_);
    for (int s = 0; s < kSubcells * kSubcells * kSubcells; ++s) {
      const Eigen::Vector3d at =
          Eigen::Vector3i(s % kSubcells, s / kSubcells % kSubcells, s / (kSubcells * kSubcells))
              .cast<double>();
      const Eigen::Vector3d lo =
          corner + at.cwiseProduct(sub_size) - Eigen::Vector3d::Constant(slack);
      const Eigen::Vector3d hi = corner + (at + Eigen::Vector3d::Ones()).cwiseProduct(sub_size) +
                                 Eigen::Vector3d::Constant(slack);
      const Kind sub_kind = ClassifyBox(static_cast<int>(padded), lo, hi, slack);
      sub_kinds.words[s >> 5] |= static_cast<std::uint64_t>(sub_kind) << (2 * (s & 31));
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
