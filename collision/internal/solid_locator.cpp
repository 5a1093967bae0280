#include "collision/internal/solid_locator.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "acd/internal/face_intersections.h"
#include "acd/internal/side_of_mesh.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"

namespace acdplan::collision::internal {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// Whether the surfaces of the closed parts `a` and `b` share a point: a pair of their triangles
// that touch or cross (exact predicates). The two are indexed apart, so a shared position counts
// as a common point.
bool SurfacesMeet(const acd::TriangleMesh& a, const acd::TriangleMesh& b) {
  acd::TriangleMesh both;
  const Eigen::Index va = a.vertices.rows(), fa = a.triangles.rows();
  both.vertices.resize(va + b.vertices.rows(), 3);
  both.vertices << a.vertices, b.vertices;
  both.triangles.resize(fa + b.triangles.rows(), 3);
  both.triangles << a.triangles, (b.triangles.array() + static_cast<int>(va)).matrix();
  for (const auto& [f, g] : acd::internal::IntersectingFacePairs(both)) {
    if (f < fa && g >= fa) return true;  // pairs are (f, g) with f < g
  }
  return false;
}

}  // namespace

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
  std::unique_ptr<acd::internal::SideOfMesh<Mesh>> side;
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
  impl_->side = std::make_unique<acd::internal::SideOfMesh<Impl::Mesh>>(impl_->mesh);
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

bool MeshLocator3d::ContainsInInterior(const Eigen::Vector3d& p) const {
  if (!box_.contains(p)) return false;
  return (*impl_->side)(Kernel::Point_3(p.x(), p.y(), p.z())) == CGAL::ON_BOUNDED_SIDE;
}

ExactObstacleLocator::ExactObstacleLocator(const ObstacleSet& obstacles, bool skip_open)
    : dimension_(obstacles.dimension), obstacle_count_(static_cast<int>(obstacles.meshes.size())) {
  if (dimension_ == 2) {
    for (const acd::Polygon2d& polygon : obstacles.polygons) polygons_.emplace_back(polygon);
    return;
  }
  std::vector<size_t> piece_component;
  for (size_t i = 0; i < obstacles.components.size(); ++i) {
    const ObstacleComponent& component = obstacles.components[i];
    piece_of_component_.push_back(-1);
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
    piece_of_component_.back() = static_cast<int>(pieces_.size());
    pieces_.emplace_back(component.mesh);
    piece_obstacle_.push_back(component.obstacle);
    piece_component.push_back(i);
    all_pieces_.push_back(static_cast<int>(all_pieces_.size()));
  }
  // Nesting depth of each closed part among its obstacle's closed parts. Part i nests in part j
  // only if j's box holds i's (cheap, and necessary), a vertex of i is strictly inside j, and
  // their surfaces do not meet: then all of i is inside j. A vertex on j's surface means they
  // meet.
  std::vector<int> depth(pieces_.size(), 0);
  for (size_t i = 0; i < pieces_.size(); ++i) {
    const acd::TriangleMesh& mesh_i = obstacles.components[piece_component[i]].mesh;
    const Eigen::Vector3d probe = mesh_i.vertices.row(mesh_i.triangles(0, 0)).transpose();
    for (size_t j = 0; j < pieces_.size(); ++j) {
      if (j == i || piece_obstacle_[j] != piece_obstacle_[i] ||
          !pieces_[j].box().contains(pieces_[i].box()) || !pieces_[j].ContainsInInterior(probe)) {
        continue;
      }
      if (!SurfacesMeet(mesh_i, obstacles.components[piece_component[j]].mesh)) ++depth[i];
    }
  }
  has_cavities_.assign(static_cast<size_t>(obstacle_count_), 0);
  for (size_t i = 0; i < pieces_.size(); ++i) {
    piece_weight_.push_back(depth[i] % 2 == 0 ? 1 : -1);
    if (piece_weight_.back() < 0) has_cavities_[static_cast<size_t>(piece_obstacle_[i])] = 1;
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
  return WindingPositive(all_pieces_, p);
}

bool ExactObstacleLocator::InsideAmong(const std::vector<int>& components,
                                       const Eigen::Vector3d& p) const {
  std::vector<int> pieces;
  for (const int c : components) {
    const int i = piece_of_component_[static_cast<size_t>(c)];
    if (i >= 0) pieces.push_back(i);
  }
  // Pieces follow the components' order, which groups them by obstacle.
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
  return WindingPositive(pieces, p);
}

bool ExactObstacleLocator::WindingPositive(const std::vector<int>& pieces,
                                           const Eigen::Vector3d& p) const {
  // Sum the winding per obstacle (its pieces are consecutive); without cavities the first
  // piece that contains p decides.
  int winding = 0;
  int current = -1;
  for (const int k : pieces) {
    const size_t i = static_cast<size_t>(k);
    if (piece_obstacle_[i] != current) {
      if (winding > 0) return true;
      winding = 0;
      current = piece_obstacle_[i];
    }
    // A cavity's surface belongs to the solid: a part of weight -1 counts only its interior.
    if (piece_weight_[i] > 0 ? !pieces_[i].Contains(p) : !pieces_[i].ContainsInInterior(p)) {
      continue;
    }
    if (!has_cavities_[static_cast<size_t>(current)]) return true;
    winding += piece_weight_[i];
  }
  return winding > 0;
}

}  // namespace acdplan::collision::internal
