#include "acd/internal/closed_shells.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>

#include "acd/internal/segment_crossings.h"
#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using ShellPoint = Epick::Point_3;
using ShellTriangle = Epick::Triangle_3;
using FaceBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, size_t>;

// A point beyond `value` on the side of `sign` (+1 or -1), 1 or |value| away, saturated at the
// largest double: then beyond it unless `value` is that double itself.
double CoordinateBeyond(double value, int sign) {
  const double far = value + sign * std::max(1.0, std::abs(value));
  return std::clamp(far, std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max());
}

// Whether `p` lies outside `box` in some coordinate.
bool IsOutsideBox(const ShellPoint& p, const Eigen::AlignedBox3d& box) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] < box.min()[k] || p[k] > box.max()[k]) return true;
  }
  return false;
}

// The winding number of the closed shell `triangles` (boxes `face_boxes`, all within `box`)
// about `p`, a point off it, counted along segments from p to beyond `box` in directions drawn
// from `rng`, until one meets no edge or vertex: a ray through one has probability 0.
int WindingAlongRandomRays(const std::vector<ShellTriangle>& triangles,
                           const std::vector<FaceBox>& face_boxes, const Eigen::AlignedBox3d& box,
                           const ShellPoint& p, RandomEngine& rng) {
  std::vector<size_t> candidates;
  for (int attempt = 0; attempt < 64; ++attempt) {
    const Eigen::Vector3d d(UniformReal(rng, -1.0, 1.0), UniformReal(rng, -1.0, 1.0),
                            UniformReal(rng, -1.0, 1.0));
    // Along d, scaled so that its largest component reaches beyond the box.
    int axis = 0;
    const double largest = d.cwiseAbs().maxCoeff(&axis);
    if (!(largest > 0.0)) continue;
    const int sign = d[axis] > 0.0 ? 1 : -1;
    const double bound = sign > 0 ? box.max()[axis] : box.min()[axis];
    const double reach = std::abs(CoordinateBeyond(bound, sign) - p[axis]) / largest;
    double to[3];
    for (int k = 0; k < 3; ++k) {
      to[k] = std::clamp(p[k] + reach * d[k], std::numeric_limits<double>::lowest(),
                         std::numeric_limits<double>::max());
    }
    const ShellPoint end(to[0], to[1], to[2]);
    if (!std::isfinite(reach) || !IsOutsideBox(end, box)) continue;
    const CGAL::Bbox_3 segment_box = p.bbox() + end.bbox();
    candidates.clear();
    for (const FaceBox& face : face_boxes) {
      if (CGAL::do_overlap(face.bbox(), segment_box)) candidates.push_back(face.info());
    }
    if (const std::optional<int> winding = SegmentCrossings(triangles, candidates, p, end)) {
      return *winding;
    }
  }
  throw std::logic_error("EnclosingShells(): 64 rays from a point off a shell met its edges");
}

// Which side of the closed shell `triangles` (boxes `face_boxes`, all within `box`) `p` lies
// on: +1 inside (an odd number of crossings; the shell may face either way), -1 outside, 0 on
// the shell. `met`: the faces whose boxes meet the upward segment from p to height `above`,
// which must be above the shell; without it, all faces are scanned and random rays cast.
int SideOfShell(const std::vector<ShellTriangle>& triangles, const std::vector<FaceBox>& face_boxes,
                const Eigen::AlignedBox3d& box, const ShellPoint& p, const std::vector<size_t>* met,
                double above, RandomEngine& rng) {
  auto through_p = [&](size_t f) {
    const ShellTriangle& t = triangles[f];
    // The orientation first: it rules out nearly every face for less than has_on()'s solve.
    return CGAL::orientation(t[0], t[1], t[2], p) == CGAL::COPLANAR && t.has_on(p);
  };
  if (met != nullptr) {
    if (std::any_of(met->begin(), met->end(), through_p)) return 0;
  } else {
    for (const FaceBox& face : face_boxes) {
      if (CGAL::do_overlap(face.bbox(), p.bbox()) && through_p(face.info())) return 0;
    }
  }
  std::optional<int> winding;
  if (met != nullptr) {
    winding = SegmentCrossings(triangles, *met, p, ShellPoint(p.x(), p.y(), above));
  }
  if (!winding) winding = WindingAlongRandomRays(triangles, face_boxes, box, p, rng);
  return *winding % 2 != 0 ? 1 : -1;
}

}  // namespace

int VolumeSign(const TriangleMesh& mesh, const std::vector<int>& faces) {
  if (faces.empty()) return 0;
  // Tetrahedra about a vertex of the shell (MeshVolume's choice), not the origin, so that the
  // terms stay small for far meshes.
  const Eigen::Vector3d origin = mesh.vertices.row(mesh.triangles(faces[0], 0)).transpose();
  double sum = 0, magnitude = 0;
  for (const int f : faces) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose() - origin;
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose() - origin;
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose() - origin;
    sum += a.dot(b.cross(c));
    // The permanent of |a|, |b|, |c|: the sum of the determinant's terms in absolute value.
    const Eigen::Vector3d x = a.cwiseAbs(), y = b.cwiseAbs(), z = c.cwiseAbs();
    magnitude += x.x() * (y.y() * z.z() + y.z() * z.y()) + x.y() * (y.z() * z.x() + y.x() * z.z()) +
                 x.z() * (y.x() * z.y() + y.y() * z.x());
  }
  // Each determinant (of rounded differences) is off by at most ~10 u times its permanent, and
  // the sum adds n u of the magnitude; twice that is a safe bound (u = 2^-53).
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double bound = 2 * (10 + static_cast<double>(faces.size())) * u * magnitude;
  if (std::abs(sum) > bound) return sum > 0 ? 1 : -1;
  using Q = CGAL::Exact_rational;
  // Returns a value: with GMP's C++ numbers, `Q - Q` is an expression template holding
  // references to the two temporaries, which would dangle once the lambda returns.
  auto exact = [&](int v, int k) -> Q { return Q(mesh.vertices(v, k)) - Q(origin(k)); };
  Q total = 0;
  for (const int f : faces) {
    Q p[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) p[i][k] = exact(mesh.triangles(f, i), k);
    }
    total += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
             p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
             p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  return CGAL::sign(total);
}

int VolumeSign(const TriangleMesh& mesh) {
  std::vector<int> faces(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(faces.begin(), faces.end(), 0);
  return VolumeSign(mesh, faces);
}

std::vector<std::vector<int>> EnclosingShells(const TriangleMesh& mesh,
                                              const std::vector<std::vector<int>>& shells) {
  const size_t count = shells.size();
  std::vector<Eigen::AlignedBox3d> boxes(count);
  std::vector<std::set<int>> vertices(count);
  for (size_t i = 0; i < count; ++i) {
    for (const int f : shells[i]) {
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.triangles(f, k);
        vertices[i].insert(v);
        boxes[i].extend(Eigen::Vector3d(mesh.vertices.row(v).transpose()));
      }
    }
  }
  auto point = [&](int v) {
    return ShellPoint(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  };
  // The queries: shell i may lie inside shell j, tested at a vertex of i off j (with no
  // crossing, the whole of i is on its side of j).
  struct Query {
    size_t inner;
    ShellPoint probe;
  };
  std::vector<std::vector<Query>> queries(count);  // Per shell j.
  for (size_t i = 0; i < count; ++i) {
    for (size_t j = 0; j < count; ++j) {
      if (i == j || !boxes[j].contains(boxes[i])) continue;
      for (const int v : vertices[i]) {
        if (!vertices[j].count(v)) {
          queries[j].push_back({i, point(v)});
          break;
        }
      }
    }
  }
  std::vector<std::vector<int>> enclosing(count);
  RandomEngine rng(1);  // Only for rays that must be cast again.
  std::vector<ShellTriangle> triangles;
  std::vector<FaceBox> face_boxes, ray_boxes;
  for (size_t j = 0; j < count; ++j) {
    if (queries[j].empty()) continue;
    triangles.clear();
    face_boxes.clear();
    for (const int f : shells[j]) {
      triangles.emplace_back(point(mesh.triangles(f, 0)), point(mesh.triangles(f, 1)),
                             point(mesh.triangles(f, 2)));
      face_boxes.emplace_back(triangles.back().bbox(), triangles.size() - 1);
    }
    // Every query's ray upward first, beyond the top of the shell (exactly vertical); the
    // faces whose boxes its segment's box meets, found for all of them at once.
    const double above = CoordinateBeyond(boxes[j].max().z(), 1);
    const bool upward = above > boxes[j].max().z();
    ray_boxes.clear();
    for (size_t q = 0; q < queries[j].size(); ++q) {
      const ShellPoint& p = queries[j][q].probe;
      ray_boxes.emplace_back(p.bbox() + ShellPoint(p.x(), p.y(), above).bbox(), q);
    }
    std::vector<std::vector<size_t>> met(queries[j].size());
    CGAL::box_intersection_d(
        ray_boxes.begin(), ray_boxes.end(), face_boxes.begin(), face_boxes.end(),
        [&](const FaceBox& ray, const FaceBox& face) { met[ray.info()].push_back(face.info()); });
    for (size_t q = 0; q < queries[j].size(); ++q) {
      const size_t i = queries[j][q].inner;
      int side = SideOfShell(triangles, face_boxes, boxes[j], queries[j][q].probe,
                             upward ? &met[q] : nullptr, above, rng);
      // A probe on j (where i touches it): the next vertex of i off j decides.
      for (auto v = vertices[i].begin(); side == 0 && v != vertices[i].end(); ++v) {
        if (vertices[j].count(*v) || point(*v) == queries[j][q].probe) continue;
        side = SideOfShell(triangles, face_boxes, boxes[j], point(*v), nullptr, above, rng);
      }
      if (side > 0) enclosing[i].push_back(static_cast<int>(j));
    }
  }
  return enclosing;  // Each list ascending, as j ascends.
}

}  // namespace acdplan::acd::internal
