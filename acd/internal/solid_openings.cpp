#include "acd/internal/solid_openings.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include "acd/concavity.h"
#include "acd/internal/box_sweep.h"
#include "acd/internal/even_odd_regions.h"
#include "acd/internal/exact_rounding.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/internal/subtree.h"
#include "acd/polygon2d.h"

namespace acdplan::acd::internal {
namespace {

using Point2 = Eigen::Vector2d;
constexpr double kInf = std::numeric_limits<double>::infinity();
using Polygon2 = std::vector<Point2>;

double Cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Sutherland-Hodgman: the part of convex `subject` inside the counter-clockwise convex `clip`,
// on points in doubles (Eigen) or exact (CGAL); `area(a, b, p)` is twice the signed area of
// triangle abp, >= 0 when p is on or left of a->b.
template <class Point, class Area>
std::vector<Point> ClipConvex(std::vector<Point> subject, const std::vector<Point>& clip,
                              Area area) {
  for (size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Point& a = clip[i];
    const Point& b = clip[(i + 1) % clip.size()];
    std::vector<Point> out;
    for (size_t j = 0; j < subject.size(); ++j) {
      const Point& p = subject[j];
      const Point& q = subject[(j + 1) % subject.size()];
      const auto sp = area(a, b, p), sq = area(a, b, q);
      const bool p_in = sp >= 0, q_in = sq >= 0;
      if (p_in) out.push_back(p);
      if (p_in != q_in) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    subject = std::move(out);
  }
  return subject;
}

// ClipConvex() in exact arithmetic, rounded once at the end.
Polygon2 ClipConvexExact(const Polygon2& subject, const Polygon2& clip) {
  using Exact = CGAL::Epeck::Point_2;
  auto exact = [](const Polygon2& polygon) {
    std::vector<Exact> out;
    for (const Point2& p : polygon) out.emplace_back(p.x(), p.y());
    return out;
  };
  const std::vector<Exact> kept =
      ClipConvex(exact(subject), exact(clip), [](const Exact& a, const Exact& b, const Exact& p) {
        return CGAL::determinant(b - a, p - a);
      });
  Polygon2 rounded;
  for (const Exact& p : kept) rounded.push_back(RoundToDouble(p));
  return rounded;
}

// Whether every point of `points` lies within `margin` of the counter-clockwise convex `polygon`.
bool NearConvex(const Polygon2& points, const Polygon2& polygon, double margin) {
  for (const Point2& p : points) {
    bool inside = true;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Point2& a = polygon[i];
      const Point2 e = polygon[(i + 1) % polygon.size()] - a;
      if (Cross(a, a + e, p) < 0) inside = false;
      const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + s * e - p).norm());
    }
    if (!inside && nearest > margin) return false;
  }
  return true;
}

// The region that both the triangles `below[s]` and `above[t]` of the pairs (., ., s, t) in
// [first, last) cover (EvenOddRegions(); the triangles of one side tile their part of the
// plane), without pieces and holes of at most `sliver` area: rounding in projecting the faces
// to the plane leaves such specks where they should meet exactly.
std::vector<Polygon2d> SharedRegions(const std::vector<Polygon2>& below,
                                     const std::vector<Polygon2>& above,
                                     std::vector<std::array<int, 4>>::const_iterator first,
                                     std::vector<std::array<int, 4>>::const_iterator last,
                                     double sliver) {
  // The triangles of one side in some pair, each once.
  auto layer = [first, last](int side, const std::vector<Polygon2>& triangles) {
    std::vector<int> indices;
    for (auto pair = first; pair != last; ++pair) indices.push_back((*pair)[side]);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    std::vector<Ring2d> rings;
    for (const int i : indices) rings.push_back(triangles[static_cast<size_t>(i)]);
    return rings;
  };
  std::vector<Polygon2d> regions;
  for (Polygon2d& region : EvenOddRegions({layer(2, below), layer(3, above)})) {
    region.holes.erase(
        std::remove_if(region.holes.begin(), region.holes.end(),
                       [sliver](const Ring2d& hole) { return -SignedArea(hole) <= sliver; }),
        region.holes.end());
    if (acd::Area(region) > sliver) regions.push_back(std::move(region));
  }
  return regions;
}

struct PlaneFaces {
  std::vector<Polygon2> below, above;  // counter-clockwise triangles in plane coordinates
};

}  // namespace

void ComputeOpenings(Decomposition3d* decomposition, OpeningDetail detail) {
  Decomposition3d& d = *decomposition;
  d.openings.clear();
  const int nodes = static_cast<int>(d.tree.size());
  double scale = 0;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const Component3d& c : d.components) {
    boxes.push_back(BoundingBox(c.mesh));
    if (c.mesh.vertices.rows() > 0) scale = std::max(scale, boxes.back().diagonal().norm());
  }
  const double tol = 1e-9 * std::max(scale, 1e-300);
  const double sliver = 1e-10 * scale * scale;  // Clipping slivers are no opening.
  std::vector<std::tuple<int, int, int, Opening3d>> found;
  for (int node = 0; node < nodes; ++node) {
    const HierarchyNode3d& cut_node = d.tree[static_cast<size_t>(node)];
    if (cut_node.children.empty()) continue;
    const Eigen::Vector3d n = cut_node.cut.normal;
    const double offset = cut_node.cut.offset;
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);  // (u, v, n) right-handed
    // The leaves below the node.
    std::vector<int> leaves;
    for (const int x : SubtreeDepthFirst(d.tree, node)) {
      const int component = d.tree[static_cast<size_t>(x)].component;
      if (component >= 0) leaves.push_back(component);
    }
    std::sort(leaves.begin(), leaves.end());  // merged leaves share a component
    leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
    // The cut piece was no larger than its leaves together, and its cap is planar to within
    // kInPlaneTolerance of its size (SplitByPlane).
    Eigen::AlignedBox3d piece_box;
    for (const int leaf : leaves) piece_box.extend(boxes[static_cast<size_t>(leaf)]);
    const double near_plane =
        tol + (piece_box.isEmpty() ? 0.0 : kInPlaneTolerance * piece_box.diagonal().norm());
    std::map<int, PlaneFaces> faces;
    for (int leaf : leaves) {
      const TriangleMesh& mesh = d.components[static_cast<size_t>(leaf)].mesh;
      for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
        std::array<Eigen::Vector3d, 3> p;
        bool in_plane = true;
        for (int k = 0; k < 3; ++k) {
          p[static_cast<size_t>(k)] = mesh.vertices.row(mesh.triangles(f, k));
          in_plane = in_plane && std::abs(n.dot(p[static_cast<size_t>(k)]) - offset) <= near_plane;
        }
        if (!in_plane) continue;
        const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
        const double len = normal.norm();
        if (!(len > 0)) continue;
        const double along = normal.dot(n) / len;
        if (std::abs(along) < 0.99) continue;
        Polygon2 tri;
        for (const auto& q : p) tri.emplace_back(u.dot(q), v.dot(q));
        if (SignedArea(tri) < 0) std::reverse(tri.begin(), tri.end());
        (along > 0 ? faces[leaf].below : faces[leaf].above).push_back(tri);
      }
    }
    // The pairs of a face below the plane (of leaf a) and one above it (of leaf b != a) whose
    // boxes meet, grown by tol: faces farther apart share no area above rounding. In the order
    // (a, b, face of a, face of b).
    std::vector<std::pair<int, int>> below_at, above_at;  // (leaf, index in its faces)
    std::vector<IdBox> below_boxes, above_boxes;
    auto add_boxes = [tol](int leaf, const std::vector<Polygon2>& triangles,
                           std::vector<std::pair<int, int>>* at, std::vector<IdBox>* boxes) {
      for (size_t i = 0; i < triangles.size(); ++i) {
        IdBox box{{kInf, kInf}, {-kInf, -kInf}, static_cast<int>(at->size())};
        for (const Point2& q : triangles[i]) {
          for (int k = 0; k < 2; ++k) {
            box.lo[k] = std::min(box.lo[k], q[k] - tol);
            box.hi[k] = std::max(box.hi[k], q[k] + tol);
          }
        }
        boxes->push_back(box);
        at->emplace_back(leaf, static_cast<int>(i));
      }
    };
    for (const auto& [leaf, f] : faces) {
      add_boxes(leaf, f.below, &below_at, &below_boxes);
      add_boxes(leaf, f.above, &above_at, &above_boxes);
    }
    std::vector<std::array<int, 4>> pairs;  // (a, b, s, t)
    ForEachOverlap(below_boxes, above_boxes, [&](int i, int j) {
      const auto [a, s] = below_at[static_cast<size_t>(i)];
      const auto [b, t] = above_at[static_cast<size_t>(j)];
      if (a != b) pairs.push_back({a, b, s, t});
    });
    std::sort(pairs.begin(), pairs.end());
    for (size_t first = 0, last = 0; first < pairs.size(); first = last) {
      const int a = pairs[first][0], b = pairs[first][1];
      while (last < pairs.size() && pairs[last][0] == a && pairs[last][1] == b) ++last;
      double area = 0;
      std::vector<Polygon2> parts;
      for (size_t k = first; k < last; ++k) {
        const Polygon2& s = faces.at(a).below[static_cast<size_t>(pairs[k][2])];
        const Polygon2& t = faces.at(b).above[static_cast<size_t>(pairs[k][3])];
        Polygon2 x = ClipConvex(s, t, Cross);
        if (x.size() < 3) continue;
        // Where an edge of s crosses one of t at a tiny angle, the rounded crossing can slide
        // along them, past a corner of t (off t's component).
        if (!NearConvex(x, s, 1e-3 * tol) || !NearConvex(x, t, 1e-3 * tol)) {
          x = ClipConvexExact(s, t);
          if (x.size() < 3) continue;
        }
        const double ax = SignedArea(x);
        if (ax > sliver) {
          area += ax;
          parts.push_back(std::move(x));
        }
      }
      if (!(area > tol * scale)) continue;
      const bool forward = a < b;  // a is below: the normal n points from a into b
      if (detail == OpeningDetail::kAdjacency) {
        Opening3d opening;
        opening.component_a = std::min(a, b);
        opening.component_b = std::max(a, b);
        opening.normal = forward ? n : Eigen::Vector3d(-n);
        opening.area = area;
        found.emplace_back(opening.component_a, opening.component_b, node, std::move(opening));
        continue;
      }
      // A convex shared region is one part, or parts whose hull has their area: its outline.
      // Else the region is taken exactly, as the area that both sides' faces cover.
      std::vector<Polygon2d> regions;
      if (parts.size() == 1) {
        regions.push_back({std::move(parts.front()), {}});
      } else {
        Polygon2 all;
        for (const Polygon2& p : parts) all.insert(all.end(), p.begin(), p.end());
        Polygon2 hull = ConvexHull(all);
        if (std::abs(SignedArea(hull) - area) <= 1e-9 * area) {
          regions.push_back({std::move(hull), {}});
        } else {
          regions = SharedRegions(faces.at(a).below, faces.at(b).above, pairs.begin() + first,
                                  pairs.begin() + last, sliver);
        }
      }
      for (Polygon2d& region : regions) {
        // From the lower-indexed component into the other; counter-clockwise about the normal.
        Opening3d opening;
        opening.component_a = std::min(a, b);
        opening.component_b = std::max(a, b);
        opening.normal = forward ? n : Eigen::Vector3d(-n);
        opening.area = acd::Area(region);
        auto lift = [&](Polygon2 ring) {
          if (!forward) std::reverse(ring.begin(), ring.end());
          std::vector<Eigen::Vector3d> lifted;
          for (const Point2& q : ring) lifted.push_back(u * q.x() + v * q.y() + n * offset);
          return lifted;
        };
        opening.polygon = lift(std::move(region.outer));
        for (Polygon2& hole : region.holes) opening.holes.push_back(lift(std::move(hole)));
        found.emplace_back(opening.component_a, opening.component_b, node, std::move(opening));
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
    return std::tie(std::get<0>(x), std::get<1>(x), std::get<2>(x)) <
           std::tie(std::get<0>(y), std::get<1>(y), std::get<2>(y));
  });
  for (auto& f : found) d.openings.push_back(std::move(std::get<3>(f)));
}

}  // namespace acdplan::acd::internal
