#pragma once
// A planar workspace: a bounds rectangle and obstacle polygons.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::envs {

/// A 2D planning world. The free space is `bounds` minus the union of `obstacles`
/// (envs/free_space2d.h). Obstacles may overlap each other, touch or cross the bounds, or lie
/// partly outside them.
struct Workspace2d {
  Eigen::AlignedBox2d bounds;             ///< The world rectangle [units]; non-empty.
  std::vector<acd::Polygon2d> obstacles;  ///< Obstacles; prepared (acd::PreparePolygon).
  std::string description;                ///< One line saying what the world is for; may be empty.
};

/// `bounds` as a counter-clockwise rectangle polygon.
acd::Polygon2d BoundsPolygon(const Eigen::AlignedBox2d& bounds);

/// Checks `bounds` (finite, xmin < xmax, ymin < ymax) and prepares every obstacle with
/// acd::PreparePolygon(), naming it "<where>: obstacle k".
/// @returns the workspace with cleaned obstacles.
/// @throws InputError naming `where` and the rule broken.
Workspace2d PrepareWorkspace2d(const Workspace2d& raw, const std::string& where);

}  // namespace acdplan::envs
