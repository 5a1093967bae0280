#pragma once
// A hand-made 2D component for the planning tests' small decompositions.

#include <Eigen/Core>

#include "acd/decomposition2d.h"

namespace acdplan::planning::testing {

/// The axis-aligned square [x, x + size] x [y, y + size] as a component (its own hull).
inline acd::Component2d Square(double x, double y, double size) {
  acd::Component2d c;
  c.polygon.outer = {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
  c.hull = c.polygon.outer;
  c.centroid = Eigen::Vector2d(x + size / 2, y + size / 2);
  return c;
}

}  // namespace acdplan::planning::testing
