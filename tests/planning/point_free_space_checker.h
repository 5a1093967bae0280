#pragma once
// Test helper: a point robot is valid iff it lies in the free space polygons (even-odd rule
// over the outer ring and the holes). A stand-in for collision:: in the sampler tests.

#include <Eigen/Core>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::planning::testing {

inline bool InsideRing(const acd::Ring2d& ring, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

inline bool InsideFreeSpace(const std::vector<acd::Polygon2d>& free_space,
                            const Eigen::Vector2d& p) {
  for (const acd::Polygon2d& polygon : free_space) {
    if (!InsideRing(polygon.outer, p)) continue;
    bool in_hole = false;
    for (const acd::Ring2d& hole : polygon.holes) in_hole = in_hole || InsideRing(hole, p);
    if (!in_hole) return true;
  }
  return false;
}

}  // namespace acdplan::planning::testing
