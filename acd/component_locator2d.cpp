#include "acd/component_locator2d.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "acd/internal/ring_locator.h"

namespace acdplan::acd {

struct ComponentLocator2d::Impl {
  std::vector<internal::RingLocator> components;
  std::vector<Eigen::AlignedBox2d> boxes;
  Eigen::AlignedBox2d box;  ///< Of every component.
  int columns = 1, rows = 1;
  Eigen::Vector2d cells_per_unit = Eigen::Vector2d::Zero();
  std::vector<int> cell_begin;  ///< Components of cell c: cell_items[cell_begin[c] .. [c + 1]).
  std::vector<int> cell_items;

  /// The cell column (row) of coordinate `v` along `axis`, clamped to the grid in double
  /// first: a far query point's offset may exceed int's range (converting it would be
  /// undefined); NaN (an infinite offset times a zero scale) goes to cell 0.
  int Cell(double v, int axis, int count) const {
    const double t = std::floor((v - box.min()[axis]) * cells_per_unit[axis]);
    if (!(t > 0.0)) return 0;
    if (t >= count - 1) return count - 1;
    return static_cast<int>(t);
  }
};

ComponentLocator2d::ComponentLocator2d(const Decomposition2d& decomposition)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  for (const Component2d& component : decomposition.components) {
    m.components.emplace_back(component.polygon);
    Eigen::AlignedBox2d box;
    for (const Point2d& p : component.polygon.outer) box.extend(p);
    m.boxes.push_back(box);
    m.box.extend(box);
  }
  const int n = static_cast<int>(m.components.size());
  if (n == 0) return;
  // About one cell per component, shaped like the common box.
  const Eigen::Vector2d size = m.box.sizes();
  const double aspect = size.y() > 0 && size.x() > 0 ? size.x() / size.y() : 1.0;
  m.columns = std::clamp(static_cast<int>(std::round(std::sqrt(n * aspect))), 1, 1024);
  m.rows = std::clamp((n + m.columns - 1) / m.columns, 1, 1024);
  m.cells_per_unit = Eigen::Vector2d(size.x() > 0 ? m.columns / size.x() : 0.0,
                                     size.y() > 0 ? m.rows / size.y() : 0.0);
  std::vector<std::vector<int>> cells(static_cast<size_t>(m.columns * m.rows));
  for (int c = 0; c < n; ++c) {
    const Eigen::AlignedBox2d& b = m.boxes[c];
    for (int row = m.Cell(b.min().y(), 1, m.rows); row <= m.Cell(b.max().y(), 1, m.rows); ++row) {
      for (int column = m.Cell(b.min().x(), 0, m.columns);
           column <= m.Cell(b.max().x(), 0, m.columns); ++column) {
        cells[static_cast<size_t>(row * m.columns + column)].push_back(c);
      }
    }
  }
  m.cell_begin.push_back(0);
  for (const std::vector<int>& cell : cells) {
    m.cell_items.insert(m.cell_items.end(), cell.begin(), cell.end());
    m.cell_begin.push_back(static_cast<int>(m.cell_items.size()));
  }
}

ComponentLocator2d::~ComponentLocator2d() = default;
ComponentLocator2d::ComponentLocator2d(ComponentLocator2d&&) noexcept = default;
ComponentLocator2d& ComponentLocator2d::operator=(ComponentLocator2d&&) noexcept = default;

int ComponentLocator2d::Locate(const Point2d& p) const {
  const Impl& m = *impl_;
  if (m.components.empty() || !m.box.contains(p)) return -1;
  const int cell = m.Cell(p.y(), 1, m.rows) * m.columns + m.Cell(p.x(), 0, m.columns);
  for (int k = m.cell_begin[cell]; k < m.cell_begin[cell + 1]; ++k) {
    const int c = m.cell_items[k];
    if (m.boxes[c].contains(p) && m.components[c].InsideParity(p)) return c;
  }
  return -1;
}

}  // namespace acdplan::acd
