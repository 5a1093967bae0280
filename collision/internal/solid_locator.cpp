#include "collision/internal/solid_locator.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "acd/prepare_mesh.h"
#include "base/input_error.h"

namespace acdplan::collision::internal {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
}

PolygonLocator2d::PolygonLocator2d(const acd::Polygon2d& polygon) {
  auto add_ring = [&](const acd::Ring2d& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      Eigen::Vector2d a = ring[i], b = ring[(i + 1) % ring.size()];
      box_.extend(a);
      if (a.y() > b.y()) std::swap(a, b);
      edges_.push_back({a, b});
    }
  };
  add_ring(polygon.outer);
  for (const acd::Ring2d& hole : polygon.holes) add_ring(hole);
  // About two edges per slab on average: long vertical runs (walls) touch many slabs, short
  // edges one.
  const int slabs = std::max(1, static_cast<int>(edges_.size() / 2));
  const double height = box_.sizes().y();
  slab_height_ = height > 0 ? height / slabs : 1.0;
  auto slab_of = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - box_.min().y()) / slab_height_)), 0,
                      slabs - 1);
  };
  std::vector<std::vector<int>> lists(static_cast<size_t>(slabs));
  for (size_t e = 0; e < edges_.size(); ++e) {
    for (int s = slab_of(edges_[e].a.y()); s <= slab_of(edges_[e].b.y()); ++s) {
      lists[static_cast<size_t>(s)].push_back(static_cast<int>(e));
    }
  }
  slab_begin_.push_back(0);
  for (const auto& list : lists) {
    slab_edges_.insert(slab_edges_.end(), list.begin(), list.end());
    slab_begin_.push_back(static_cast<int>(slab_edges_.size()));
  }
}

bool PolygonLocator2d::Contains(const Eigen::Vector2d& p) const {
  if (!box_.contains(p)) return false;
  const int slabs = static_cast<int>(slab_begin_.size()) - 1;
  const int s = std::clamp(static_cast<int>(std::floor((p.y() - box_.min().y()) / slab_height_)), 0,
                           slabs - 1);
  const Kernel::Point_2 q(p.x(), p.y());
  bool inside = false;
  for (int k = slab_begin_[static_cast<size_t>(s)]; k < slab_begin_[static_cast<size_t>(s) + 1];
       ++k) {
    const Edge& e = edges_[static_cast<size_t>(slab_edges_[static_cast<size_t>(k)])];
    // Half-open rule on y (a.y <= p.y < b.y) counts each vertex once; horizontal edges never
    // straddle. The ray goes to +x: the edge crosses it iff p is left of the upward edge.
    if (p.y() < e.a.y() || p.y() > e.b.y()) continue;
    if (p.x() > std::max(e.a.x(), e.b.x())) {
      // Entirely left of p: no crossing, unless p lies on a horizontal edge (boundary).
      continue;
    }
    const CGAL::Orientation o =
        CGAL::orientation(Kernel::Point_2(e.a.x(), e.a.y()), Kernel::Point_2(e.b.x(), e.b.y()), q);
    if (o == CGAL::COLLINEAR) {
      // On the edge's supporting line within its y range (and x range by the tests above and
      // collinearity): p is on the boundary.
      if (p.x() >= std::min(e.a.x(), e.b.x())) return true;
      continue;
    }
    if (p.y() == e.b.y()) continue;  // half-open: the upper end does not count
    if (o == CGAL::LEFT_TURN) inside = !inside;
  }
  return inside;
}

struct MeshLocator3d::Impl {
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh mesh;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
};

MeshLocator3d::MeshLocator3d(const acd::TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  std::vector<Impl::Mesh::Vertex_index> vs;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    const Eigen::Vector3d p = mesh.vertices.row(i);
    box_.extend(p);
    vs.push_back(impl_->mesh.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  }
  // Side_of_triangle_mesh only needs the faces (ray parity); add_face would reject
  // inconsistently oriented neighbours, so faces are added as an unconnected soup when needed.
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    auto a = vs[static_cast<size_t>(mesh.triangles(f, 0))];
    auto b = vs[static_cast<size_t>(mesh.triangles(f, 1))];
    auto c = vs[static_cast<size_t>(mesh.triangles(f, 2))];
    if (impl_->mesh.add_face(a, b, c) == Impl::Mesh::null_face()) {
      auto a2 = impl_->mesh.add_vertex(impl_->mesh.point(a));
      auto b2 = impl_->mesh.add_vertex(impl_->mesh.point(b));
      auto c2 = impl_->mesh.add_vertex(impl_->mesh.point(c));
      impl_->mesh.add_face(a2, b2, c2);
    }
  }
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Impl::Mesh, Kernel>>(impl_->mesh);
  // Build the AABB tree now, so concurrent queries never race to build it.
  (*impl_->side)(Kernel::Point_3(box_.min().x() - 1, box_.min().y(), box_.min().z()));
}

MeshLocator3d::~MeshLocator3d() = default;
MeshLocator3d::MeshLocator3d(MeshLocator3d&&) noexcept = default;
MeshLocator3d& MeshLocator3d::operator=(MeshLocator3d&&) noexcept = default;

bool MeshLocator3d::Contains(const Eigen::Vector3d& p) const {
  if (!box_.contains(p)) return false;
  return (*impl_->side)(Kernel::Point_3(p.x(), p.y(), p.z())) != CGAL::ON_UNBOUNDED_SIDE;
}

ExactObstacleLocator::ExactObstacleLocator(const ObstacleSet& obstacles, bool skip_open)
    : dimension_(obstacles.dimension), obstacle_count_(static_cast<int>(obstacles.meshes.size())) {
  if (dimension_ == 2) {
    for (const acd::Polygon2d& polygon : obstacles.polygons) polygons_.emplace_back(polygon);
    return;
  }
  for (size_t i = 0; i < obstacles.components.size(); ++i) {
    const ObstacleComponent& component = obstacles.components[i];
    if (!component.closed) {
      if (skip_open) {
        ++skipped_open_;
        continue;
      }
      throw InputError(
          "PointLocator(): exact point location needs closed obstacle meshes: obstacle " +
          std::to_string(component.obstacle) + " (part " + std::to_string(i) +
          ") is open: " + acd::PrepareMesh(component.mesh).defects.first);
    }
    pieces_.emplace_back(component.mesh);
    piece_obstacle_.push_back(component.obstacle);
  }
}

bool ExactObstacleLocator::Inside(const Eigen::Vector3d& p) const {
  if (dimension_ == 2) {
    const Eigen::Vector2d q = p.head<2>();
    for (const PolygonLocator2d& polygon : polygons_) {
      if (polygon.Contains(q)) return true;
    }
    return false;
  }
  // Pieces of one obstacle are consecutive; flip a parity per obstacle.
  bool parity = false;
  int current = -1;
  for (size_t i = 0; i < pieces_.size(); ++i) {
    if (piece_obstacle_[i] != current) {
      if (parity) return true;
      parity = false;
      current = piece_obstacle_[i];
    }
    if (pieces_[i].Contains(p)) parity = !parity;
  }
  return parity;
}

}  // namespace acdplan::collision::internal
