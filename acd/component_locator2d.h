#pragma once
// Which component of a 2D decomposition holds a point (dissertation Ch. VI.A, point location).

#include <memory>
#include <vector>

#include "acd/decomposition2d.h"
#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Exact point location among the components of a Decomposition2d.
///
/// The components' bounding boxes are binned into a uniform grid of about one cell per
/// component over their common box; a query tests only the components listed in its cell, each
/// by even-odd ray crossing with exact orientation predicates (for the double coordinates of
/// the point and the components). So a query costs O(components per cell x edges per slab),
/// about O(1) on ordinary decompositions, instead of a loop over every component.
///
/// A point exactly on a cut shared by two components may be given to either of them; a point
/// outside every component gives -1. Thread-safe after construction: queries are const.
class ComponentLocator2d {
 public:
  /// Indexes `decomposition.components` (the locator keeps its own copy of what it needs).
  explicit ComponentLocator2d(const Decomposition2d& decomposition);
  ~ComponentLocator2d();
  ComponentLocator2d(ComponentLocator2d&&) noexcept;
  ComponentLocator2d& operator=(ComponentLocator2d&&) noexcept;

  /// Index of the component holding `p`, or -1.
  int Locate(const Point2d& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acdplan::acd
