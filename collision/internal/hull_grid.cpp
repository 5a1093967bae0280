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

}  // namespace

HullGrid::HullGrid(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
                   const std::vector<Eigen::AlignedBox3d>& boxes, double slack) {
  for (const auto& hull : planes) {
    for (Eigen::Index r = 0; r < hull.rows(); ++r) {
      Eigen::Vector4d plane = hull.row(r).transpose();
      plane(3) += slack;
      planes_.push_back(plane);
    }
    hull_plane_begin_.push_back(static_cast<int>(planes_.size()));
  }
  std::vector<Eigen::AlignedBox3d> loose = boxes;
  for (auto& box : loose) {
    box.min().array() -= slack;
    box.max().array() += slack;
    bounds_.extend(box);
  }
  if (loose.empty()) return;

  // Cells about cubic: edge h with (extent / h) cells per axis, about kTargetCells in all; an
  // extent of zero (a flat set of hulls) gets one cell on that axis.
  const Eigen::Vector3d extent = bounds_.sizes().cwiseMax(1e-300);
  const double h = std::cbrt(extent.prod() / kTargetCells);
  for (int k = 0; k < 3; ++k) {
    cells_[k] = std::clamp(static_cast<int>(std::ceil(extent[k] / h)), 1, kTargetCells);
    cell_size_[k] = extent[k] / cells_[k];
  }
  const size_t cell_count = static_cast<size_t>(cells_.prod());
  covered_.assign(cell_count, 0);
  std::vector<std::vector<int>> lists(cell_count);

  // Cell boxes are grown by the slack, so that a point rounded into a neighbouring cell still
  // lies in the box its cell was classified by. A cell is left out of a hull's list only if a
  // plane of the hull has the whole (grown) cell beyond it by another slack: the plain test
  // would then say "outside" for every point of it, even after rounding.
  for (size_t i = 0; i < loose.size(); ++i) {
    const int begin = hull_plane_begin_[i], end = hull_plane_begin_[i + 1];
    Eigen::Vector3i lo, hi;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::clamp(
          static_cast<int>(std::floor((loose[i].min()[k] - bounds_.min()[k]) / cell_size_[k])) - 1,
          0, cells_[k] - 1);
      hi[k] = std::clamp(
          static_cast<int>(std::floor((loose[i].max()[k] - bounds_.min()[k]) / cell_size_[k])) + 1,
          0, cells_[k] - 1);
    }
    for (int z = lo.z(); z <= hi.z(); ++z) {
      for (int y = lo.y(); y <= hi.y(); ++y) {
        for (int x = lo.x(); x <= hi.x(); ++x) {
          const Eigen::Vector3d cmin = bounds_.min() +
                                       Eigen::Vector3d(x, y, z).cwiseProduct(cell_size_) -
                                       Eigen::Vector3d::Constant(slack);
          const Eigen::Vector3d cmax = cmin + cell_size_ + Eigen::Vector3d::Constant(2 * slack);
          if (!Eigen::AlignedBox3d(cmin, cmax).intersects(loose[i])) continue;
          bool separated = false, inside = true;
          for (int k = begin; k < end && !separated; ++k) {
            const Eigen::Vector3d n = planes_[static_cast<size_t>(k)].head<3>();
            const double d = planes_[static_cast<size_t>(k)](3);
            separated = MinOver(n, cmin, cmax) > d + slack;
            // Covered only with a slack to spare, so that the plain test agrees on every point.
            inside = inside && MaxOver(n, cmin, cmax) <= d - slack;
          }
          if (separated) continue;
          const size_t c =
              (static_cast<size_t>(z) * static_cast<size_t>(cells_.y()) + static_cast<size_t>(y)) *
                  static_cast<size_t>(cells_.x()) +
              static_cast<size_t>(x);
          lists[c].push_back(static_cast<int>(i));
          if (inside && begin < end) covered_[c] = 1;
        }
      }
    }
  }
  cell_begin_.reserve(cell_count + 1);
  cell_begin_.push_back(0);
  for (const auto& list : lists) {
    cell_hulls_.insert(cell_hulls_.end(), list.begin(), list.end());
    cell_begin_.push_back(static_cast<int>(cell_hulls_.size()));
  }
}

int HullGrid::CellOf(const Eigen::Vector3d& p) const {
  if (cell_begin_.empty() || !bounds_.contains(p)) return -1;
  int index[3];
  for (int k = 0; k < 3; ++k) {
    index[k] =
        std::clamp(static_cast<int>((p[k] - bounds_.min()[k]) / cell_size_[k]), 0, cells_[k] - 1);
  }
  return (index[2] * cells_.y() + index[1]) * cells_.x() + index[0];
}

bool HullGrid::HullContains(int hull, const Eigen::Vector3d& p) const {
  const Eigen::Vector4d q(p.x(), p.y(), p.z(), -1.0);
  for (int k = hull_plane_begin_[static_cast<size_t>(hull)];
       k < hull_plane_begin_[static_cast<size_t>(hull) + 1]; ++k) {
    if (planes_[static_cast<size_t>(k)].dot(q) > 0) return false;
  }
  return true;
}

bool HullGrid::AnyContains(const Eigen::Vector3d& p) const {
  const int c = CellOf(p);
  if (c < 0) return false;
  if (covered_[static_cast<size_t>(c)]) return true;
  for (int k = cell_begin_[static_cast<size_t>(c)]; k < cell_begin_[static_cast<size_t>(c) + 1];
       ++k) {
    if (HullContains(cell_hulls_[static_cast<size_t>(k)], p)) return true;
  }
  return false;
}

void HullGrid::Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const {
  const int c = CellOf(p);
  if (c < 0) return;
  for (int k = cell_begin_[static_cast<size_t>(c)]; k < cell_begin_[static_cast<size_t>(c) + 1];
       ++k) {
    const int hull = cell_hulls_[static_cast<size_t>(k)];
    if (HullContains(hull, p)) out->push_back(hull);
  }
}

}  // namespace acdplan::collision::internal
