#include "collision/collision_world.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "acd/concavity.h"
#include "acd/convex_hull3d.h"
#include "acd/decompose2d.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"
#include "collision/internal/convex_separation.h"
#include "collision/internal/hull_grid.h"
#include "collision/internal/inner_polytope.h"
#include "collision/internal/mesh_building.h"
#include "collision/internal/outer_polytope.h"
#include "collision/internal/solid_locator.h"
#include "collision/internal/triangle_tree.h"

namespace acdplan::collision {
namespace {

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

Geometry MakeBvh(const std::vector<const acd::TriangleMesh*>& meshes) {
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  for (const acd::TriangleMesh* mesh : meshes) {
    std::vector<fcl::Vector3d> v;
    std::vector<fcl::Triangle> t;
    for (Eigen::Index i = 0; i < mesh->vertices.rows(); ++i) v.push_back(mesh->vertices.row(i));
    for (Eigen::Index f = 0; f < mesh->triangles.rows(); ++f) {
      t.emplace_back(mesh->triangles(f, 0), mesh->triangles(f, 1), mesh->triangles(f, 2));
    }
    model->addSubModel(v, t);
  }
  model->endModel();
  model->computeLocalAABB();
  return model;
}

Geometry MakeConvex(const acd::TriangleMesh& hull) {
  auto v = std::make_shared<std::vector<fcl::Vector3d>>();
  for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) v->push_back(hull.vertices.row(i));
  auto f = std::make_shared<std::vector<int>>();
  for (Eigen::Index k = 0; k < hull.triangles.rows(); ++k) {
    f->insert(f->end(), {3, hull.triangles(k, 0), hull.triangles(k, 1), hull.triangles(k, 2)});
  }
  auto convex = std::make_shared<fcl::Convexd>(v, static_cast<int>(hull.triangles.rows()), f);
  convex->computeLocalAABB();
  return convex;
}

fcl::CollisionRequestd BooleanRequest() {
  fcl::CollisionRequestd request(1, false);
  // libccd's GJK: FCL 0.7's own solver (GST_INDEP) misses some Convex-Convex contacts (the
  // randomized tests found hull misses on an L-shaped robot and a cube robot with it).
  request.gjk_solver_type = fcl::GST_LIBCCD;
  return request;
}

fcl::DistanceRequestd DistanceRequest() {
  fcl::DistanceRequestd request;
  // FCL's own GJK for distances: libccd's Convex distances came out up to 30% too large (a
  // hull distance above the exact mesh distance in the tests), so each query picks the solver
  // the tests validated for it.
  request.gjk_solver_type = fcl::GST_INDEP;
  return request;
}

bool Collide(const fcl::CollisionGeometryd* a, const fcl::Transform3d& ta,
             const fcl::CollisionGeometryd* b, const fcl::Transform3d& tb) {
  static const fcl::CollisionRequestd request = BooleanRequest();
  fcl::CollisionResultd result;
  fcl::collide(a, ta, b, tb, request, result);
  return result.isCollision();
}

/// A contact between two convex shapes as FCL's two GJK implementations see it.
enum class ConvexContact {
  kNone,      ///< Neither finds one.
  kFound,     ///< libccd finds one (the solver the tests validated for convex pairs).
  kDoubtful,  ///< Only FCL's own solver finds one.
};

/// Each of FCL's GJK implementations misses contacts the other finds: libccd missed a
/// penetration of more than 1e-3 of the robot's size between a cube robot and an ACD hull of
/// ob_chair_gothic that FCL's own solver and the triangle test both found; FCL's own missed the
/// contacts noted in BooleanRequest(). A hull test must never miss, so a contact either finds
/// counts; one only FCL's own finds is kDoubtful, and confirmed exactly even on a convex piece.
ConvexContact CollideConvex(const fcl::CollisionGeometryd* a, const fcl::Transform3d& ta,
                            const fcl::CollisionGeometryd* b, const fcl::Transform3d& tb) {
  if (Collide(a, ta, b, tb)) return ConvexContact::kFound;
  static const fcl::CollisionRequestd request = [] {
    fcl::CollisionRequestd r = BooleanRequest();
    r.gjk_solver_type = fcl::GST_INDEP;
    return r;
  }();
  fcl::CollisionResultd result;
  fcl::collide(a, ta, b, tb, request, result);
  return result.isCollision() ? ConvexContact::kDoubtful : ConvexContact::kNone;
}

double Distance(const fcl::CollisionGeometryd* a, const fcl::Transform3d& ta,
                const fcl::CollisionGeometryd* b, const fcl::Transform3d& tb) {
  static const fcl::DistanceRequestd request = DistanceRequest();
  fcl::DistanceResultd result;
  fcl::distance(a, ta, b, tb, request, result);
  return std::max(result.min_distance, 0.0);
}

/// The triangles of `mesh`.
std::vector<internal::Triangle3> Triangles(const acd::TriangleMesh& mesh) {
  std::vector<internal::Triangle3> out;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    internal::Triangle3& t = out.emplace_back();
    for (int k = 0; k < 3; ++k) {
      t[static_cast<size_t>(k)] = mesh.vertices.row(mesh.triangles(f, k)).transpose();
    }
  }
  return out;
}

/// `hull` (a closed convex mesh) as vertices and supporting face planes.
internal::ConvexPolytope Polytope(const acd::TriangleMesh& hull) {
  internal::ConvexPolytope polytope;
  for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) {
    polytope.vertices.push_back(hull.vertices.row(i).transpose());
  }
  const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = acd::HullPlanes(hull);
  for (Eigen::Index r = 0; r < planes.rows(); ++r) polytope.planes.push_back(planes.row(r));
  return polytope;
}

/// The piece's internal::InnerPolytope(), kept when the mean of the piece's vertices is inside
/// the obstacle. Without cavities every part of the obstacle counts +1 in its winding rule, so
/// inside the piece's own part is inside the obstacle, and only that part's triangles bound K;
/// with cavities, every closed part of the obstacle does.
internal::ConvexPolytope InnerPolytopeOf(const ObstacleSet& set, const ObstaclePiece& piece,
                                         const internal::ExactObstacleLocator& exact,
                                         double margin) {
  const Eigen::AlignedBox3d box(piece.box.min().array() - margin, piece.box.max().array() + margin);
  const bool own_part_only = !exact.has_cavities(piece.obstacle);
  std::vector<internal::Triangle3> near;
  std::vector<int> parts;
  for (size_t c = 0; c < set.components.size(); ++c) {
    const ObstacleComponent& part = set.components[c];
    if (part.obstacle != piece.obstacle || !part.closed) continue;
    if (own_part_only && static_cast<int>(c) != piece.component) continue;
    parts.push_back(static_cast<int>(c));
    for (const internal::Triangle3& t : Triangles(part.mesh)) {
      if (Eigen::AlignedBox3d(t[0]).extend(t[1]).extend(t[2]).intersects(box)) near.push_back(t);
    }
  }
  const Eigen::Vector3d center = piece.solid.vertices.colwise().mean().transpose();
  return internal::InnerPolytope(near, piece.planes, center, margin, [&](const Eigen::Vector3d& p) {
    return exact.InsideAmong(parts, p);
  });
}

/// Face planes (besides the six axis-aligned ones) of the polytope a concave 3D piece's hull
/// tests take when its hull has more (internal::OuterPolytope()).
constexpr int kMaxTestedHullPlanes = 58;

/// The sides of the regular polygon that stands in for a disc robot in the face-plane pre-test:
/// circumscribed, so it contains the disc and a separation it finds is one of the disc.
constexpr int kDiscPolygonSides = 16;

}  // namespace

struct CollisionWorld::Impl {
  // Robot (body frame).
  Geometry robot_exact;                // null for a point robot
  Geometry robot_hull;                 // convex hull (== robot_exact for a disc)
  std::vector<Geometry> robot_pieces;  // exact convex pieces of a non-convex polygon robot
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();     // a point of the robot (containment)
  std::optional<internal::MeshLocator3d> robot_locator;  // closed 3D robot: obstacle inside it
  Geometry point_probe;  // point robot: a zero-radius sphere for distances
  // The robot's hull for the face-plane pre-test of every hull test (a disc: its circumscribed
  // polygon's prism); no vertices for a point robot. When `polytope_on_robot`, its vertices are
  // points of the robot, so one inside a hull is a contact with that hull.
  internal::ConvexPolytope robot_polytope;
  bool polytope_on_robot = false;
  // A closed 3D robot that equals its hull (robot_polytope): kHullsExact confirms a hull hit by
  // testing that polytope against the piece's triangles near it (piece_trees), with the hull's
  // edge directions (body frame) for the separating axis test, instead of a BVH-BVH query.
  bool robot_convex = false;
  std::vector<Eigen::Vector3d> robot_edges;
  // Broadphase query objects of robot_hull / point_probe at the identity, built once. A query
  // copies one (RobotAt()) instead of constructing fcl::CollisionObject from the shared
  // geometry: that constructor recomputes the geometry's local AABB, i.e. writes to geometry
  // every concurrent query reads (a data race inside libfcl, which TSan cannot see).
  std::unique_ptr<fcl::CollisionObjectd> robot_hull_object;
  std::unique_ptr<fcl::CollisionObjectd> point_probe_object;

  // Obstacles (world frame).
  Geometry all_bvh;  // kBvh
  std::optional<internal::ExactObstacleLocator> exact_locator;
  std::vector<Geometry> piece_hulls;                      // fcl::Convexd
  std::vector<internal::ConvexPolytope> piece_polytopes;  // the same hulls, for the pre-test
  // 3D kHullsExact: per piece, a polytope inside the obstacle (InnerPolytopeOf()), so that a
  // robot vertex inside it is a hit with no confirmation; no planes where there is none (2D,
  // pieces of open parts, pieces whose hull is exact, or none found).
  std::vector<internal::ConvexPolytope> piece_inner;
  double margin = 0;  // the pre-test's tolerance for rounding [units]
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> hull_objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  std::vector<Geometry> piece_bvhs;  // kHullsExact confirmation (3D: the component's triangles
                                     // that may meet the piece's hull, input coordinates)
  std::vector<internal::TriangleTree> piece_trees;  // the same triangles, when robot_convex
  std::vector<std::optional<internal::PolygonLocator2d>> piece_polygons;  // 2D containment
  internal::HullGrid hull_grid;  // point robot, kHulls / kHullsExact
  int dimension = 2;

  // True if the part (ObstacleComponent) of piece `i` lies inside the robot at `pose` (closed 3D
  // robot only): with no surface contact, one vertex decides. With contact elsewhere on the
  // component the answer may be true too, which is then right for another reason.
  bool PieceInsideRobot(const ObstacleSet& set, size_t i, const Eigen::Isometry3d& pose) const {
    if (!robot_locator) return false;
    const ObstaclePiece& piece = set.pieces[i];
    const acd::TriangleMesh& surface =
        piece.component >= 0 ? set.components[static_cast<size_t>(piece.component)].mesh
                             : piece.solid;
    const Eigen::Vector3d v = surface.vertices.row(0).transpose();
    return robot_locator->Contains(pose.inverse() * v);
  }

  // 3D: whether `p` is inside an obstacle by the parts in `components` (the exact locator's
  // winding rule). The callers list every part one of whose piece hulls contains p; the hulls
  // cover their part, so that is every part that contains p.
  bool PartsContain(const std::vector<int>& components, const Eigen::Vector3d& p) const {
    return !components.empty() && exact_locator->InsideAmong(components, p);
  }

  // A hit on piece `i`'s hull is a hit on the obstacle, with no confirmation: the piece is
  // convex (it is its hull), not from a repaired part (ObstaclePiece::repaired) and, in 3D, no
  // part of its obstacle is a cavity (inside a part of an obstacle with cavities may still be
  // outside the obstacle).
  bool HullIsExact(const ObstacleSet& set, size_t i) const {
    const ObstaclePiece& piece = set.pieces[i];
    return piece.convex && !piece.repaired &&
           (piece.component < 0 || !exact_locator->has_cavities(piece.obstacle));
  }
};

namespace {

/// The robot's broadphase object at `pose`, copied from `prototype` (see Impl): reads the
/// shared geometry only.
fcl::CollisionObjectd RobotAt(const fcl::CollisionObjectd& prototype,
                              const Eigen::Isometry3d& pose) {
  fcl::CollisionObjectd robot(prototype);
  robot.setTransform(pose);
  robot.computeAABB();
  return robot;
}

size_t PieceOf(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2) {
  void* data = o1->getUserData() ? o1->getUserData() : o2->getUserData();
  return reinterpret_cast<size_t>(data) - 1;
}

}  // namespace

Eigen::Isometry3d CollisionWorld::Lift(const Eigen::Isometry2d& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear().topLeftCorner<2, 2>() = pose.linear();
  out.translation().head<2>() = pose.translation();
  return out;
}

CollisionWorld::CollisionWorld(std::shared_ptr<const ObstacleSet> obstacles,
                               const envs::Robot& robot, const CollisionWorldOptions& options)
    : obstacles_(std::move(obstacles)),
      robot_(robot),
      options_(options),
      impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const ObstacleSet& set = *obstacles_;
  m.dimension = set.dimension;
  const std::string shape = ToString(robot.shape);
  if (set.dimension == 3 &&
      (robot.shape == envs::RobotShape::kDisc || robot.shape == envs::RobotShape::kPolygon)) {
    throw InputError("CollisionWorld(): a " + shape +
                     " robot moves in the plane; this world is 3D (use a mesh or a point)");
  }
  if (set.dimension == 2 && robot.shape == envs::RobotShape::kMesh) {
    throw InputError(
        "CollisionWorld(): a mesh robot moves in 3D; this world is 2D (use a point, a disc or "
        "a polygon)");
  }

  // Robot geometry.
  const double h = set.extrusion_height;
  switch (robot.shape) {
    case envs::RobotShape::kPoint:
      m.point_probe = std::make_shared<fcl::Sphered>(0.0);
      m.point_probe->computeLocalAABB();
      break;
    case envs::RobotShape::kDisc:
      if (!(robot.radius > 0)) throw InputError("CollisionWorld(): disc radius must be > 0");
      m.robot_exact = std::make_shared<fcl::Cylinderd>(robot.radius, h / 2);
      m.robot_exact->computeLocalAABB();
      m.robot_hull = m.robot_exact;
      {
        const double r = robot.radius / std::cos(M_PI / kDiscPolygonSides);
        acd::Ring2d ring;
        for (int k = 0; k < kDiscPolygonSides; ++k) {
          const double a = 2 * M_PI * k / kDiscPolygonSides;
          ring.emplace_back(r * std::cos(a), r * std::sin(a));
        }
        m.robot_polytope = Polytope(internal::ExtrudeConvexRing(ring, -h / 4, h / 4));
      }
      break;
    case envs::RobotShape::kPolygon: {
      const acd::TriangleMesh prism = internal::ExtrudePolygon(robot.polygon, -h / 4, h / 4);
      m.robot_exact = MakeBvh({&prism});
      const acd::TriangleMesh hull =
          internal::ExtrudeConvexRing(acd::ConvexHull(robot.polygon.outer), -h / 4, h / 4);
      m.robot_hull = MakeConvex(hull);
      m.robot_polytope = Polytope(hull);
      m.polytope_on_robot = true;  // corners of the outline at the prism's ends
      const acd::Decomposition2d pieces = acd::Decompose2d(robot.polygon, {});
      if (pieces.components.size() > 1 || !robot.polygon.holes.empty()) {
        for (const acd::Component2d& c : pieces.components) {
          m.robot_pieces.push_back(MakeConvex(internal::ExtrudeConvexRing(c.hull, -h / 4, h / 4)));
        }
      }
      m.witness = Eigen::Vector3d(robot.polygon.outer[0].x(), robot.polygon.outer[0].y(), 0);
      break;
    }
    case envs::RobotShape::kMesh: {
      acd::CheckTriangleMesh(robot.mesh, "CollisionWorld(): robot mesh");
      m.robot_exact = MakeBvh({&robot.mesh});
      std::vector<Eigen::Vector3d> points;
      for (Eigen::Index i = 0; i < robot.mesh.vertices.rows(); ++i) {
        points.push_back(robot.mesh.vertices.row(i).transpose());
      }
      const acd::TriangleMesh hull = acd::ConvexHull3(points, 1e-9);
      m.robot_hull = MakeConvex(hull);
      m.robot_polytope = Polytope(hull);
      // A flat robot's hull is thickened: its corners are then not all the robot's.
      m.polytope_on_robot =
          std::all_of(m.robot_polytope.vertices.begin(), m.robot_polytope.vertices.end(),
                      [&points](const Eigen::Vector3d& v) {
                        return std::find(points.begin(), points.end(), v) != points.end();
                      });
      m.witness = robot.mesh.vertices.row(robot.mesh.triangles(0, 0)).transpose();
      const acd::PreparedMesh prepared =
          acd::PrepareMesh(robot.mesh, {}, "CollisionWorld(): robot mesh");
      const auto& closed = prepared.closed_parts;
      if (std::all_of(closed.begin(), closed.end(), [](bool c) { return c; })) {
        m.robot_locator.emplace(prepared.mesh);
        m.robot_convex = m.polytope_on_robot && closed.size() == 1 &&
                         internal::EqualsItsHull(prepared.mesh, hull);
        if (m.robot_convex) m.robot_edges = internal::EdgeDirections(hull.vertices, hull.triangles);
      }
      break;
    }
  }

  // Obstacles.
  std::vector<const acd::TriangleMesh*> meshes;
  for (const auto& mesh : set.meshes) meshes.push_back(&mesh);
  m.all_bvh = MakeBvh(meshes);
  m.exact_locator.emplace(set, /*skip_open=*/true);
  std::vector<fcl::CollisionObjectd*> objects;
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>> planes;
  std::vector<Eigen::AlignedBox3d> boxes;
  m.margin = 1e-12 * (1 + set.bounds.sizes().norm() + set.bounds.max().cwiseAbs().maxCoeff() +
                      set.bounds.min().cwiseAbs().maxCoeff());
  for (size_t i = 0; i < set.pieces.size(); ++i) {
    const ObstaclePiece& piece = set.pieces[i];
    // A concave piece's hit is confirmed on its triangles anyway: its hull tests may take a
    // polytope with few faces around a hull with many (2,318 faces on teapot's body patch), which
    // the face-plane pre-test and GJK read face by face and vertex by vertex.
    const acd::TriangleMesh tested =
        set.dimension == 3 && !m.HullIsExact(set, i)
            ? internal::OuterPolytope(piece.hull, piece.planes, kMaxTestedHullPlanes)
            : piece.hull;
    m.piece_hulls.push_back(MakeConvex(tested));
    m.piece_polytopes.push_back(Polytope(tested));
    m.piece_inner.push_back(set.dimension == 3 && piece.closed && !m.HullIsExact(set, i)
                                ? InnerPolytopeOf(set, piece, *m.exact_locator, m.margin)
                                : internal::ConvexPolytope{});
    m.hull_objects.push_back(std::make_unique<fcl::CollisionObjectd>(m.piece_hulls.back()));
    // User data = piece index + 1; the robot's object has none.
    m.hull_objects.back()->setUserData(reinterpret_cast<void*>(i + 1));
    m.hull_objects.back()->computeAABB();
    objects.push_back(m.hull_objects.back().get());
    if (set.dimension == 2) {
      m.piece_bvhs.push_back(MakeBvh({&piece.solid}));
      m.piece_polygons.emplace_back(std::in_place, piece.polygon);
    } else {
      const acd::TriangleMesh near = internal::SubMesh(
          set.components[static_cast<size_t>(piece.component)].mesh, piece.triangles);
      m.piece_bvhs.push_back(near.triangles.rows() > 0 ? MakeBvh({&near}) : nullptr);
      m.piece_trees.emplace_back(m.robot_convex ? Triangles(near)
                                                : std::vector<internal::Triangle3>{});
      m.piece_polygons.emplace_back();
    }
    planes.push_back(piece.planes);
    boxes.push_back(piece.box);
  }
  if (m.robot_hull) m.robot_hull_object = std::make_unique<fcl::CollisionObjectd>(m.robot_hull);
  if (m.point_probe) {
    m.point_probe_object = std::make_unique<fcl::CollisionObjectd>(m.point_probe);
  }
  m.manager.registerObjects(objects);
  m.manager.setup();
  m.hull_grid = internal::HullGrid(planes, boxes, m.margin, set.dimension == 2);
}

CollisionWorld::~CollisionWorld() = default;

bool CollisionWorld::IsValid(const Eigen::Isometry3d& pose, CollisionMode mode) const {
  checks_.fetch_add(1, std::memory_order_relaxed);
  const Impl& m = *impl_;
  const ObstacleSet& set = *obstacles_;
  bool collides = false;
  const Eigen::Vector3d witness = pose * m.witness;

  if (!m.robot_exact) {  // point robot
    if (mode == CollisionMode::kBvh) {
      collides = m.exact_locator->Inside(witness);
    } else if (mode == CollisionMode::kHulls) {
      collides = m.hull_grid.AnyContains(witness);
    } else {
      std::vector<int> candidates;
      m.hull_grid.Candidates(witness, &candidates);
      std::vector<int> components;
      for (int i : candidates) {
        const ObstaclePiece& piece = set.pieces[static_cast<size_t>(i)];
        if (m.HullIsExact(set, static_cast<size_t>(i)) ||  // Inside its hull is inside it.
            internal::InsideBy(m.piece_inner[static_cast<size_t>(i)], witness, m.margin)) {
          collides = true;
          break;
        }
        exact_confirmations_.fetch_add(1, std::memory_order_relaxed);
        if (const auto& poly = m.piece_polygons[static_cast<size_t>(i)]) {
          if (poly->Contains(witness.head<2>())) {
            collides = true;
            break;
          }
        } else {
          components.push_back(piece.component);
        }
      }
      collides = collides || m.PartsContain(components, witness);
    }
  } else if (mode == CollisionMode::kBvh) {
    collides = Collide(m.robot_exact.get(), pose, m.all_bvh.get(), fcl::Transform3d::Identity()) ||
               m.exact_locator->Inside(witness);
    if (!collides && m.robot_locator) {
      const fcl::CollisionObjectd robot = RobotAt(*m.robot_hull_object, pose);
      const fcl::AABBd& box = robot.getAABB();
      for (size_t i = 0; i < set.pieces.size() && !collides; ++i) {
        const auto& pb = set.pieces[i].box;
        if (pb.min().x() < box.min_.x() || pb.min().y() < box.min_.y() ||
            pb.min().z() < box.min_.z() || pb.max().x() > box.max_.x() ||
            pb.max().y() > box.max_.y() || pb.max().z() > box.max_.z()) {
          continue;  // a piece inside the robot has its box inside the robot's box
        }
        collides = m.PieceInsideRobot(set, i, pose);
      }
    }
  } else {
    const bool exact_mode = mode == CollisionMode::kHullsExact;
    // State of this query through the broadphase callback.
    struct HitQuery {
      const Impl* m;
      const ObstacleSet* set;
      Eigen::Isometry3d pose;
      Eigen::Vector3d witness;         // world frame
      bool exact;                      // kHullsExact
      internal::ConvexPolytope robot;  // m.robot_polytope at `pose`, once Robot() placed it
      bool robot_placed = false;
      bool hit = false;
      // robot_convex: the robot's edge directions and box at `pose`, set at the first
      // confirmation.
      std::vector<Eigen::Vector3d> robot_edges;
      Eigen::AlignedBox3d robot_box;
      std::vector<int> components;  // 3D: components whose containment of witness decides
      std::uint64_t hull_tests = 0, confirmations = 0;

      // The robot's polytope at `pose`, moved at the first broadphase pair: most poses in free
      // space have none (15% of a window-wall plan's time went to moving it up front).
      const internal::ConvexPolytope& Robot() {
        if (!robot_placed) {
          m->robot_polytope.Transformed(pose, &robot);
          robot_placed = true;
        }
        return robot;
      }
    } q{&m, &set, pose, witness, exact_mode, {}, false, false, {}, {}, {}, 0, 0};
    fcl::CollisionObjectd robot = RobotAt(*m.robot_hull_object, pose);
    m.manager.collide(
        &robot, &q, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
          HitQuery& q = *static_cast<HitQuery*>(data);
          const Impl& m = *q.m;
          const size_t i = PieceOf(o1, o2);
          const fcl::Transform3d identity = fcl::Transform3d::Identity();
          ++q.hull_tests;
          // The face-plane pre-test: most boxes that overlap belong to hulls a face plane of
          // either side separates; and a corner of the robot inside a hull is a contact, which
          // on a convex piece is a collision. GJK only decides what remains.
          const internal::ConvexPolytope& hull = m.piece_polytopes[i];
          if (internal::SeparatedByAFacePlane(q.Robot(), hull, m.margin)) return false;
          if (m.polytope_on_robot && (!q.exact || m.HullIsExact(*q.set, i)) &&
              internal::AVertexInside(q.Robot(), hull, m.margin)) {
            q.hit = true;
            return true;
          }
          // A corner of the robot inside the piece's inner polytope is inside the obstacle.
          if (q.exact && m.polytope_on_robot &&
              internal::AVertexInside(q.Robot(), m.piece_inner[i], m.margin)) {
            q.hit = true;
            return true;
          }
          const ConvexContact contact =
              CollideConvex(m.robot_hull.get(), q.pose, m.piece_hulls[i].get(), identity);
          if (contact == ConvexContact::kNone) return false;
          // A convex piece is its own hull, so the hull tests below are exact for it: only a
          // concave piece needs its own triangles to confirm a hull hit.
          if (!q.exact || (m.HullIsExact(*q.set, i) && contact == ConvexContact::kFound)) {
            // Without robot_pieces, the robot's hull is the robot itself (a disc, a convex
            // polygon, a convex mesh) or, for a concave mesh, a cover of it that only kHulls
            // may take for it.
            if (m.robot_pieces.empty()) {
              if (!q.exact || m.dimension == 2 || m.robot_convex) {
                q.hit = true;
                return true;
              }
            } else {
              bool doubtful = false;
              for (const Geometry& piece : m.robot_pieces) {
                ++q.hull_tests;
                const ConvexContact part =
                    CollideConvex(piece.get(), q.pose, m.piece_hulls[i].get(), identity);
                if (part == ConvexContact::kFound || (part != ConvexContact::kNone && !q.exact)) {
                  q.hit = true;
                  return true;
                }
                doubtful = doubtful || part == ConvexContact::kDoubtful;
              }
              if (!q.exact || !doubtful) return false;
            }
          }
          ++q.confirmations;
          bool touches = false;
          if (m.robot_convex) {
            if (q.robot_edges.empty()) {
              for (const Eigen::Vector3d& e : m.robot_edges) {
                q.robot_edges.push_back(q.pose.linear() * e);
              }
              for (const Eigen::Vector3d& v : q.Robot().vertices) q.robot_box.extend(v);
            }
            touches = m.piece_trees[i].AnyNear(q.robot_box, [&q](const internal::Triangle3& t) {
              return internal::TouchesTriangle(q.Robot(), q.robot_edges, t);
            });
          } else {
            touches = m.piece_bvhs[i] &&
                      Collide(m.robot_exact.get(), q.pose, m.piece_bvhs[i].get(), identity);
          }
          // A part inside a convex robot has its triangles inside the polytope, which touches
          // them: only the BVH-BVH test, which sees surfaces, needs the containment test.
          if (touches || (!m.robot_convex && m.PieceInsideRobot(*q.set, i, q.pose))) {
            q.hit = true;
            return true;
          }
          if (const auto& poly = m.piece_polygons[i]) {
            q.hit = poly->Contains(q.witness.head<2>());
            return q.hit;
          }
          q.components.push_back(q.set->pieces[i].component);
          return false;
        });
    collides = q.hit || m.PartsContain(q.components, witness);
    hull_tests_.fetch_add(q.hull_tests, std::memory_order_relaxed);
    exact_confirmations_.fetch_add(q.confirmations, std::memory_order_relaxed);
  }
  if (collides) collisions_.fetch_add(1, std::memory_order_relaxed);
  return !collides;
}

double CollisionWorld::Clearance(const Eigen::Isometry3d& pose, CollisionMode mode) const {
  clearance_queries_.fetch_add(1, std::memory_order_relaxed);
  if (!IsValid(pose, mode)) return 0.0;
  const Impl& m = *impl_;
  const fcl::CollisionGeometryd* exact = m.robot_exact ? m.robot_exact.get() : m.point_probe.get();
  const Geometry& hull_geometry = m.robot_exact ? m.robot_hull : m.point_probe;
  if (mode == CollisionMode::kBvh) {
    return Distance(exact, pose, m.all_bvh.get(), fcl::Transform3d::Identity());
  }
  struct Context {
    const Impl* m;
    fcl::Transform3d pose;
    const fcl::CollisionGeometryd* exact;
    const fcl::CollisionGeometryd* hull;
    bool refine;
    double best = std::numeric_limits<double>::infinity();
  } context{&m, pose, exact, hull_geometry.get(), mode == CollisionMode::kHullsExact};
  fcl::CollisionObjectd robot =
      RobotAt(m.robot_exact ? *m.robot_hull_object : *m.point_probe_object, pose);
  m.manager.distance(
      &robot, &context,
      [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data, double& dist) {
        Context& c = *static_cast<Context*>(data);
        const size_t i = PieceOf(o1, o2);
        double d =
            Distance(c.hull, c.pose, c.m->piece_hulls[i].get(), fcl::Transform3d::Identity());
        if (!c.refine && !c.m->robot_pieces.empty() && d < c.best) {
          // The exact convex pieces of the robot give a tighter (still conservative) bound.
          double pieces = std::numeric_limits<double>::infinity();
          for (const Geometry& piece : c.m->robot_pieces) {
            pieces = std::min(pieces, Distance(piece.get(), c.pose, c.m->piece_hulls[i].get(),
                                               fcl::Transform3d::Identity()));
          }
          d = pieces;
        }
        if (c.refine && d < c.best) {
          d = Distance(c.exact, c.pose, c.m->piece_bvhs[i].get(), fcl::Transform3d::Identity());
        }
        c.best = std::min(c.best, d);
        dist = std::min(dist, c.best);
        return c.best <= 0;
      });
  return std::isfinite(context.best) ? context.best : std::numeric_limits<double>::infinity();
}

CollisionCounters CollisionWorld::counters() const {
  CollisionCounters c;
  c.checks = checks_.load(std::memory_order_relaxed);
  c.collisions = collisions_.load(std::memory_order_relaxed);
  c.clearance_queries = clearance_queries_.load(std::memory_order_relaxed);
  c.hull_tests = hull_tests_.load(std::memory_order_relaxed);
  c.exact_confirmations = exact_confirmations_.load(std::memory_order_relaxed);
  return c;
}

void CollisionWorld::ResetCounters() {
  checks_ = 0;
  collisions_ = 0;
  clearance_queries_ = 0;
  hull_tests_ = 0;
  exact_confirmations_ = 0;
}

}  // namespace acdplan::collision
