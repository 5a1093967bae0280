#include "envs/mesh_footprint.h"

#include <CGAL/Boolean_set_operations_2.h>

#include <algorithm>
#include <iterator>

#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "envs/internal/exact_polygons.h"

namespace acdplan::envs {
namespace {

using Point = internal::ExactPoint;
using Polygon = internal::ExactPolygon;
using internal::ToDouble;

}  // namespace

std::vector<acd::Polygon2d> Footprint(const acd::TriangleMesh& mesh, const std::string& where,
                                      const FootprintOptions& options) {
  std::vector<Polygon> triangles;
  triangles.reserve(static_cast<size_t>(mesh.triangles.rows()));
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
    const double z_low = std::min({a.z(), b.z(), c.z()});
    const double z_high = std::max({a.z(), b.z(), c.z()});
    if (z_high < options.z_min || z_low > options.z_max) continue;
    Polygon triangle;
    triangle.push_back(Point(a.x(), a.y()));
    triangle.push_back(Point(b.x(), b.y()));
    triangle.push_back(Point(c.x(), c.y()));
    // The exact orientation decides: a wall seen edge-on covers no area.
    const CGAL::Orientation orientation = triangle.orientation();
    if (orientation == CGAL::COLLINEAR) continue;
    if (orientation == CGAL::CLOCKWISE) triangle.reverse_orientation();
    triangles.push_back(std::move(triangle));
  }
  std::vector<acd::Polygon2d> result;
  if (triangles.empty()) return result;
  internal::ExactPolygonSet united;
  united.join(triangles.begin(), triangles.end());
  std::vector<internal::ExactPolygonWithHoles> parts;
  united.polygons_with_holes(std::back_inserter(parts));
  for (size_t i = 0; i < parts.size(); ++i) {
    acd::Polygon2d raw{ToDouble(parts[i].outer_boundary().container()), {}};
    for (auto hole = parts[i].holes_begin(); hole != parts[i].holes_end(); ++hole) {
      raw.holes.push_back(ToDouble(hole->container()));
    }
    // CGAL's boundaries may pass a point twice (parts touching at a vertex): PreparePolygons
    // splits those into valid polygons.
    for (acd::Polygon2d& polygon :
         acd::PreparePolygons(raw, where + ": footprint part " + std::to_string(i))) {
      result.push_back(std::move(polygon));
    }
  }
  return result;
}

acd::Polygon2d FootprintOutline(const acd::TriangleMesh& mesh, const std::string& where) {
  std::vector<acd::Polygon2d> parts = Footprint(mesh, where);
  if (parts.empty()) {
    throw InputError(where +
                     ": the robot's footprint is empty (every triangle is perpendicular to the "
                     "xy plane)");
  }
  if (parts.size() > 1) {
    throw InputError(where + ": the robot's footprint has " + std::to_string(parts.size()) +
                     " separate parts (a rigid robot needs one outline)");
  }
  return parts.front();
}

}  // namespace acdplan::envs
