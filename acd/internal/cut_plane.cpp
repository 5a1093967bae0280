#include "acd/internal/cut_plane.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>

#include "acd/internal/canonical_hull.h"
#include "acd/internal/feature_grouping.h"
#include "acd/internal/hull_facets.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/mesh_measures.h"

namespace acdplan::acd::internal {
namespace {

// The lightest global cuts whose planes are tried (3 gave fewer parts on some meshes but many
// more on others, plaque and torus1 at tau_rel 0.02: docs/bench/acd3d_solid.md).
constexpr int kGlobalCuts = 1;

// The candidate planes, each listed once.
struct Candidates {
  std::vector<Plane3d> planes;
  std::vector<char> through_witness;
  // Adds the plane through `point` with normal `normal` unless it is (nearly) one already
  // listed: parallel, and both through the witness or within `tol` [units] of each other.
  void Add(const Eigen::Vector3d& normal, const Eigen::Vector3d& point, bool at_witness,
           double tol) {
    const double len = normal.norm();
    if (!(len > 1e-12)) return;
    Eigen::Vector3d n = normal / len;
    // One sign per direction, so a plane and its opposite are one candidate.
    for (int k = 0; k < 3; ++k) {
      if (std::abs(n(k)) > 1e-12) {
        if (n(k) < 0) n = -n;
        break;
      }
    }
    const double offset = n.dot(point);
    for (size_t i = 0; i < planes.size(); ++i) {
      if (std::abs(planes[i].normal.dot(n)) <= 1 - 1e-6) continue;
      if ((at_witness && through_witness[i]) || std::abs(planes[i].offset - offset) <= tol) return;
    }
    planes.push_back({n, offset});
    through_witness.push_back(at_witness);
  }
};

struct SideScore {
  bool valid = false;
  double concavity = 0.0;    // the largest over the side's pieces
  double hull_volume = 0.0;  // summed over the side's pieces
};

// The cheap score of one side piece: the volume of the hull of `hulled` and the depth of each
// of its `vertices` below that hull's planes, except the planes of the cap the cut `cut` makes:
// the cap is surface, not a bridge (Sec. V.B: a point's concavity is its distance to its
// pocket's bridge). Counted as a bridge, the cap's plane hid the depth of the points beside it:
// a torus cut through its tube's equator kept half its measured depth, and was cut into washers.
void ScorePiece(const std::vector<Eigen::Vector3d>& hulled,
                const std::vector<Eigen::Vector3d>& vertices, const Plane3d& cut, double tol,
                SideScore* score) {
  if (hulled.size() < 4) return;
  const CanonicalHull hull = MakeCanonicalHull(hulled);
  if (hull.mesh.triangles.rows() < 4 || hull.planes.rows() < 4) return;
  const double volume = MeshVolume(hull.mesh);
  if (!(volume > 0)) return;
  score->hull_volume += volume;
  const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes = hull.planes;
  // A hull plane is the cap's when every hull vertex on it is in the cut's plane: so also the
  // narrow facets that rounding tilts off the cap along its rim (a model stored in floats and
  // turned off the axes has them), which a test of the planes' equations would keep as bridges.
  // Only the planes of hull triangles with three corners in the cut's plane can be.
  const auto& corners = hull.mesh.vertices;
  auto on = [&](Eigen::Index j, Eigen::Index v) {
    return std::abs(planes(j, 3) - planes.row(j).head<3>().dot(corners.row(v).transpose())) <= tol;
  };
  std::vector<char> in_cut(static_cast<size_t>(corners.rows()));
  for (Eigen::Index v = 0; v < corners.rows(); ++v) {
    in_cut[static_cast<size_t>(v)] =
        std::abs(cut.SignedDistance(corners.row(v).transpose())) <= tol;
  }
  std::vector<char> cap(static_cast<size_t>(planes.rows()), 0), tried(cap.size(), 0);
  for (Eigen::Index t = 0; t < hull.mesh.triangles.rows(); ++t) {
    const Eigen::Vector3i tri = hull.mesh.triangles.row(t).transpose();
    if (!in_cut[static_cast<size_t>(tri(0))] || !in_cut[static_cast<size_t>(tri(1))] ||
        !in_cut[static_cast<size_t>(tri(2))]) {
      continue;
    }
    for (Eigen::Index j = 0; j < planes.rows(); ++j) {
      if (tried[static_cast<size_t>(j)] || !on(j, tri(0)) || !on(j, tri(1)) || !on(j, tri(2))) {
        continue;
      }
      tried[static_cast<size_t>(j)] = 1;
      bool only_cut = true;
      for (Eigen::Index v = 0; v < corners.rows() && only_cut; ++v) {
        only_cut = in_cut[static_cast<size_t>(v)] || !on(j, v);
      }
      cap[static_cast<size_t>(j)] = only_cut;
    }
  }
  for (const Eigen::Vector3d& p : vertices) {
    double d = 1e300;
    for (Eigen::Index j = 0; j < planes.rows(); ++j) {
      if (!cap[static_cast<size_t>(j)])
        d = std::min(d, planes(j, 3) - planes.row(j).head<3>().dot(p));
    }
    score->concavity = std::max(score->concavity, d);
  }
}

// The side `sign` (-1 below, +1 above) of `mesh` cut by `plane`, where the vertices have signed
// heights `s`: its pieces (vertices joined by edges that do not run in the plane, so two posts of a
// U cut at their base are two pieces), each hulled with the points where its edges cross. Of those
// section points (in the plane, up to rounding) only the corners of their convex polygon seen
// along `plane_axis` (the normal's largest coordinate) are hulled: the others are inside the
// hull, and in the plane of its cap facet, where each of them would cost convex_hull_3 an exact
// orientation test per cap triangle (measured: 15% of mite at tau_rel 0.05). Likewise the
// vertices of each of `caps` (the earlier cuts' caps) on this side: only their corners are hulled.
SideScore ScoreSide(const TriangleMesh& mesh, const Plane3d& plane, const Eigen::VectorXd& s,
                    int sign, double tol, int plane_axis,
                    const std::vector<VerticesInPlane>& caps) {
  const Eigen::Index n = mesh.vertices.rows();
  auto side = [&](Eigen::Index i) { return s(i) > tol ? 1 : (s(i) < -tol ? -1 : 0); };
  std::vector<int> parent(static_cast<size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[static_cast<size_t>(x)] != x) {
      x = parent[static_cast<size_t>(x)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    }
    return x;
  };
  std::vector<char> joined(static_cast<size_t>(n), 0);     // an in-plane vertex on one of its edges
  std::vector<std::pair<int, Eigen::Vector3d>> crossings;  // (vertex on this side, point)
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      if (a > b) continue;  // each edge once (its other face lists it the other way)
      const int sa = side(a), sb = side(b);
      if ((sa == sign && sb != -sign) || (sb == sign && sa != -sign)) {
        joined[static_cast<size_t>(a)] = joined[static_cast<size_t>(b)] = 1;
        const int ra = find(a), rb = find(b);
        if (ra != rb) parent[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb);
      } else if (sa * sb < 0) {
        const double t = s(a) / (s(a) - s(b));
        crossings.emplace_back(sa == sign ? a : b,
                               mesh.vertices.row(a).transpose() +
                                   t * (mesh.vertices.row(b) - mesh.vertices.row(a)).transpose());
      }
    }
  }
  // Side vertices inside the polygon of their cap's vertices on this side: not extreme.
  std::vector<char> inside_cap(static_cast<size_t>(n), 0);
  for (const VerticesInPlane& cap : caps) {
    std::map<int, std::vector<int>> by_piece;
    for (const int v : cap.vertices) {
      if (side(v) == sign) by_piece[find(v)].push_back(v);
    }
    for (const auto& [root, ids] : by_piece) {
      std::vector<Eigen::Vector3d> points;
      for (const int v : ids) points.emplace_back(mesh.vertices.row(v));
      std::vector<char> corner(ids.size(), 0);
      for (const int i : ConvexCornersAlongAxis(points, cap.axis))
        corner[static_cast<size_t>(i)] = 1;
      for (size_t k = 0; k < ids.size(); ++k) {
        if (!corner[k]) inside_cap[static_cast<size_t>(ids[k])] = 1;
      }
    }
  }
  std::map<int, std::vector<Eigen::Vector3d>> vertices, hulled, section;
  for (Eigen::Index i = 0; i < n; ++i) {
    const int si = side(i);
    if (si == sign) {
      const int root = find(static_cast<int>(i));
      vertices[root].emplace_back(mesh.vertices.row(i));
      if (!inside_cap[static_cast<size_t>(i)]) hulled[root].emplace_back(mesh.vertices.row(i));
    } else if (si == 0 && joined[static_cast<size_t>(i)]) {
      section[find(static_cast<int>(i))].emplace_back(mesh.vertices.row(i));
    }
  }
  for (const auto& [v, p] : crossings) section[find(v)].push_back(p);
  SideScore score;
  if (vertices.empty()) return score;
  for (auto& [root, measured] : vertices) {
    std::vector<Eigen::Vector3d>& pts = hulled[root];
    const auto it = section.find(root);
    if (it != section.end()) {
      for (int i : ConvexCornersAlongAxis(it->second, plane_axis))
        pts.push_back(it->second[static_cast<size_t>(i)]);
      // The section's rim is on the surface: measured too (the deepest point of a piece cut
      // along a ring of its vertices often lies on that ring).
      measured.insert(measured.end(), it->second.begin(), it->second.end());
    }
    ScorePiece(pts, measured, plane, tol, &score);
  }
  score.valid = score.hull_volume > 0;
  return score;
}

// PartAxes(): a face whose normal is within about 1.4e-3 rad of a direction faces along it (a
// flat face of a single-precision model is flat to ~1e-7), two directions within 1e-3 rad of a
// right angle are orthogonal, the normals of the kAxisCandidates largest faces are the candidate
// directions, and the part's own axes replace the world's when they face more area, by more
// than kAxesMargin of the total (equal when a model is in its design frame).
constexpr double kFacing = 1e-6;
constexpr double kOrthogonal = 1e-3;
constexpr int kAxisCandidates = 32;
constexpr double kAxesMargin = 1e-3;

// Twice the area vector of face `f` of `mesh`: (b - a) x (c - a).
Eigen::Vector3d FaceCross(const TriangleMesh& mesh, Eigen::Index f) {
  const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0));
  return (Eigen::Vector3d(mesh.vertices.row(mesh.triangles(f, 1))) - a)
      .cross(Eigen::Vector3d(mesh.vertices.row(mesh.triangles(f, 2))) - a);
}

// The area of the faces (normals `normals`, areas `areas`) that face along one of `axes`.
double FacingArea(const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& areas,
                  const std::vector<Eigen::Vector3d>& axes) {
  double sum = 0;
  for (size_t f = 0; f < normals.size(); ++f) {
    for (const Eigen::Vector3d& axis : axes) {
      if (std::abs(normals[f].dot(axis)) >= 1 - kFacing) {
        sum += areas[f];
        break;
      }
    }
  }
  return sum;
}

}  // namespace

std::array<Eigen::Vector3d, 3> WorldAxes() {
  return {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
}

std::array<Eigen::Vector3d, 3> PartAxes(const TriangleMesh& part) {
  const std::array<Eigen::Vector3d, 3> world = WorldAxes();
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> areas;
  double total = 0;
  for (Eigen::Index f = 0; f < part.triangles.rows(); ++f) {
    const Eigen::Vector3d n = FaceCross(part, f);
    const double len = n.norm();
    if (!(len > 0)) continue;
    normals.push_back(n / len);
    areas.push_back(0.5 * len);
    total += 0.5 * len;
  }
  // The largest faces, ties by index (the part is canonically numbered).
  std::vector<size_t> order(normals.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const size_t k = std::min(order.size(), static_cast<size_t>(kAxisCandidates));
  std::partial_sort(
      order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
      [&](size_t i, size_t j) { return areas[i] > areas[j] || (areas[i] == areas[j] && i < j); });
  order.resize(k);
  auto best_direction = [&](const Eigen::Vector3d* orthogonal_to, Eigen::Vector3d* out) {
    double best = 0;
    for (const size_t c : order) {
      Eigen::Vector3d d = normals[c];
      if (orthogonal_to != nullptr) {
        if (std::abs(d.dot(*orthogonal_to)) > kOrthogonal) continue;
        d = (d - d.dot(*orthogonal_to) * *orthogonal_to).normalized();
      }
      const double area = FacingArea(normals, areas, {d});
      if (area > best) best = area, *out = d;
    }
    return best > 0;
  };
  Eigen::Vector3d d1, d2;
  if (!best_direction(nullptr, &d1) || !best_direction(&d1, &d2)) return world;
  const Eigen::Vector3d d3 = d1.cross(d2);
  const double own = FacingArea(normals, areas, {d1, d2, d3});
  const double on_world = FacingArea(normals, areas, {world[0], world[1], world[2]});
  return own > on_world + kAxesMargin * total ? std::array<Eigen::Vector3d, 3>{d1, d2, d3} : world;
}

CutPlaneRanking::CutPlaneRanking(const TriangleMesh& mesh, const SolidConcavity& concavity,
                                 double tau, const std::vector<Plane3d>& caps,
                                 bool feature_grouping, bool lazy,
                                 const std::array<Eigen::Vector3d, 3>& axes)
    : mesh_(mesh), tau_(tau) {
  const Eigen::Vector3d w = concavity.witness;
  const double scale = BoundingBox(mesh).diagonal().norm();
  tol_ = kInPlaneTolerance * scale;  // as the cut classifies vertices (SplitByPlane)
  for (const Plane3d& cap : caps) {
    VerticesInPlane in_plane;
    cap.normal.cwiseAbs().maxCoeff(&in_plane.axis);
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
      if (std::abs(cap.SignedDistance(mesh.vertices.row(i).transpose())) <= tol_)
        in_plane.vertices.push_back(static_cast<int>(i));
    }
    if (in_plane.vertices.size() > 3) caps_.push_back(std::move(in_plane));
  }
  // Two planes are one candidate when parallel and this close (the planes through the witness
  // all share a point, so for them only the direction tells them apart).
  const double same = tau > 0 ? 1e-3 * tau : 1e-6 * scale;
  Candidates listed;
  std::vector<Eigen::Vector3d> pca, bisectors;
  // The pocket's principal planes (Eq. 5.3: the least-squares plane is the smallest one).
  if (!concavity.pocket_faces.empty()) {
    std::vector<int> verts;
    for (int f : concavity.pocket_faces) {
      for (int k = 0; k < 3; ++k) verts.push_back(mesh.triangles(f, k));
    }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : verts) mean += mesh.vertices.row(v).transpose();
    mean /= static_cast<double>(verts.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int v : verts) {
      const Eigen::Vector3d d = mesh.vertices.row(v).transpose() - mean;
      cov += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    for (int k = 0; k < 3; ++k) pca.push_back(eig.eigenvectors().col(k));
  }
  // The faces at the witness and the dihedral bisectors of its edges.
  auto face_normal = [&](int f) { return Eigen::Vector3d(FaceCross(mesh, f).normalized()); };
  if (concavity.witness_vertex >= 0) {
    std::map<std::pair<int, int>, std::vector<int>> edges;  // edge at the witness -> faces
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      for (int k = 0; k < 3; ++k) {
        if (mesh.triangles(f, k) != concavity.witness_vertex) continue;
        listed.Add(face_normal(static_cast<int>(f)), w, true, same);
        for (int other : {mesh.triangles(f, (k + 1) % 3), mesh.triangles(f, (k + 2) % 3)}) {
          edges[{std::min(other, concavity.witness_vertex),
                 std::max(other, concavity.witness_vertex)}]
              .push_back(static_cast<int>(f));
        }
      }
    }
    for (const auto& [edge, faces] : edges) {
      if (faces.size() != 2) continue;
      const Eigen::Vector3d n1 = face_normal(faces[0]), n2 = face_normal(faces[1]);
      if (n1.dot(n2) > 1 - 1e-6) continue;  // flat: no dihedral to bisect
      bisectors.push_back(n1 - n2);
      bisectors.push_back(n1 + n2);
    }
  } else if (concavity.witness_face >= 0) {
    listed.Add(face_normal(concavity.witness_face), w, true, same);
  }
  // On ties the first listed wins: a notch's own walls extended, then the axes, then the fits.
  if (feature_grouping) {
    FeatureGroupingOptions grouping;
    grouping.max_cuts = kGlobalCuts;
    for (const GlobalCut& cut : FindGlobalCuts(mesh, concavity, tau, grouping)) {
      listed.Add(cut.plane.normal, cut.plane.offset * cut.plane.normal, false, same);
      listed.Add(cut.plane.normal, w, true, same);
    }
  }
  for (const Eigen::Vector3d& axis : axes) listed.Add(axis, w, true, same);
  for (const auto& n : pca) listed.Add(n, w, true, same);
  for (const auto& n : bisectors) listed.Add(n, w, true, same);
  bin_ = tau > 0 ? tau / 4 : scale * 1e-3;
  volume_unit_ = std::max(1e-9 * concavity.hull_volume, 1e-300);
  for (const Plane3d& plane : listed.planes) {
    candidates_.emplace_back();
    candidates_.back().plane = plane;
    ScoreNextSide(&candidates_.back());
    if (!lazy && !candidates_.back().done) ScoreNextSide(&candidates_.back());
  }
}

void CutPlaneRanking::ScoreNextSide(Candidate* candidate) {
  const Plane3d& plane = candidate->plane;
  const Eigen::Index n = mesh_.vertices.rows();
  Eigen::VectorXd s(n);
  for (Eigen::Index i = 0; i < n; ++i)
    s(i) = plane.SignedDistance(mesh_.vertices.row(i).transpose());
  int axis = 0;
  plane.normal.cwiseAbs().maxCoeff(&axis);
  if (candidate->sides_scored == 0) {
    // The side with more vertices first: it is likelier to hold the worse side's concavity,
    // and its hull is the larger part of the volume, so its bound rules out more.
    Eigen::Index above = 0, below = 0;
    for (Eigen::Index i = 0; i < n; ++i) above += s(i) > tol_, below += s(i) < -tol_;
    candidate->first_side = above > below ? 1 : -1;
  }
  const int sign = candidate->sides_scored == 0 ? candidate->first_side : -candidate->first_side;
  const SideScore side = ScoreSide(mesh_, plane, s, sign, tol_, axis, caps_);
  ++candidate->sides_scored;
  if (!side.valid) {
    candidate->done = true;  // dropped
    return;
  }
  candidate->concavity = std::max(candidate->concavity, side.concavity);
  candidate->hull_volume += side.hull_volume;
}

std::tuple<long long, long long, size_t> CutPlaneRanking::KeyOf(size_t c) const {
  const Candidate& candidate = candidates_[c];
  const double worst = candidate.concavity;
  const long long level =
      worst <= tau_ ? 0 : 1 + static_cast<long long>(std::floor((worst - tau_) / bin_));
  // Volumes equal to rounding are ties.
  return {level, std::llround(candidate.hull_volume / volume_unit_), c};
}

std::optional<ScoredPlane> CutPlaneRanking::Next() {
  // Keys (bin, volume, index): a half-scored candidate's is a lower bound on its full key, so
  // the least full key is next once no half-scored bound is below it.
  using Key = std::tuple<long long, long long, size_t>;
  while (true) {
    std::optional<Key> best_full, best_half;
    for (size_t c = 0; c < candidates_.size(); ++c) {
      if (candidates_[c].done) continue;
      const Key key = KeyOf(c);
      std::optional<Key>& best = candidates_[c].sides_scored == 2 ? best_full : best_half;
      if (!best || key < *best) best = key;
    }
    if (!best_full && !best_half) return std::nullopt;
    if (best_half && (!best_full || *best_half < *best_full)) {
      ScoreNextSide(&candidates_[std::get<2>(*best_half)]);
      continue;
    }
    Candidate& next = candidates_[std::get<2>(*best_full)];
    next.done = true;
    return ScoredPlane{next.plane, next.concavity, next.hull_volume};
  }
}

int CutPlaneRanking::SidesScored() const {
  int count = 0;
  for (const Candidate& candidate : candidates_) count += candidate.sides_scored;
  return count;
}

}  // namespace acdplan::acd::internal
