#pragma once
// SVG pictures of 2D worlds: obstacles, the free space's ACD components and openings.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "acd/decomposition2d.h"
#include "acd/polygon2d.h"
#include "base/svg.h"
#include "envs/workspace2d.h"

namespace acdplan::envs {

/// A picture of a workspace, drawn in painting order on an SvgCanvas (base/svg.h): world
/// coordinates (y up) map to a picture 800 pixels across (y down) with a caption line below;
/// callers add their own elements (roadmaps, paths) between the layers with Add() and the
/// coordinate helpers.
class WorldSvg {
 public:
  explicit WorldSvg(const Eigen::AlignedBox2d& bounds);

  /// Picture coordinates of world x, y, and a point "x,y".
  std::string X(double x) const { return canvas_.X(x); }
  std::string Y(double y) const { return canvas_.Y(y); }
  std::string Point(const Eigen::Vector2d& p) const { return canvas_.Point(p); }
  /// Path data of a polygon with holes (use fill-rule="evenodd").
  std::string PathData(const acd::Polygon2d& polygon) const;

  /// The free space's components, each in its own fill (`distinct`) or all in one light blue.
  void AddComponents(const acd::Decomposition2d& decomposition, bool distinct);
  void AddObstacles(const std::vector<acd::Polygon2d>& obstacles);
  /// The openings between components, thick orange lines.
  void AddOpenings(const acd::Decomposition2d& decomposition);
  /// Any SVG element(s), in picture coordinates.
  void Add(const std::string& elements) { canvas_.Add(elements); }

  /// The finished document with `caption` (escaped) under the drawing.
  std::string Finish(const std::string& caption) const { return canvas_.Finish({caption}); }

 private:
  SvgCanvas canvas_;
};

/// A workspace and its free-space decomposition: obstacles, components in distinct fills,
/// openings, and `caption`.
std::string WorldToSvg(const Workspace2d& workspace, const acd::Decomposition2d& free_space,
                       const std::string& caption);

}  // namespace acdplan::envs
