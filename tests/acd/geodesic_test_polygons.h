#pragma once
// Seeded generators of simple polygons and brute-force geodesic references, shared by
// triangulate_ring_test.cpp and shortest_paths_test.cpp. Draws go through base/random.h, so a
// seed gives the same polygons with any standard library.

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "acd/internal/exact_predicates.h"
#include "acd/polygon2d.h"
#include "base/random.h"

namespace acdplan::acd::testing {

using internal::Orientation;

inline constexpr double kPi = 3.14159265358979323846;

/// Regular convex polygon with n vertices (counter-clockwise).
inline Ring2d RegularPolygon(int n, double radius = 1.0) {
  Ring2d ring;
  for (int i = 0; i < n; ++i) {
    ring.emplace_back(radius * std::cos(2 * kPi * i / n), radius * std::sin(2 * kPi * i / n));
  }
  return ring;
}

/// Star-shaped polygon around the origin: n >= 3 sorted random angles (resampled until no gap
/// reaches 0.9 pi, so the origin is in the kernel), radii in [min_radius, 1].
inline Ring2d RandomStar(int n, RandomEngine& rng, double min_radius = 0.2) {
  std::vector<double> angles(n);
  for (double max_gap = 2 * kPi; max_gap >= 0.9 * kPi;) {
    for (double& a : angles) a = UniformReal(rng, 0.0, 2 * kPi);
    std::sort(angles.begin(), angles.end());
    max_gap = angles.front() + 2 * kPi - angles.back();
    for (int i = 1; i < n; ++i) max_gap = std::max(max_gap, angles[i] - angles[i - 1]);
  }
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  Ring2d ring;
  for (double a : angles) {
    const double r = UniformReal(rng, min_radius, 1.0);
    ring.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return ring;
}

/// Comb: a base bar [0, 2 teeth] x [0, 1] with `teeth` random-height teeth on top. The tooth
/// bases all lie on the line y = 1 (collinear reflex vertices) unless `jitter` is set.
inline Ring2d RandomComb(int teeth, RandomEngine& rng, bool jitter = false) {
  auto width = [&rng] { return UniformReal(rng, 0.5, 1.6); };
  auto height = [&rng] { return UniformReal(rng, 0.5, 5.0); };
  auto wiggle = [&rng] { return UniformReal(rng, -0.1, 0.1); };
  const double w = 2.0 * teeth;
  Ring2d ring = {{0, 0}, {w, 0}, {w, 1}};
  for (int i = teeth - 1; i >= 0; --i) {
    const double x0 = 2.0 * i + 0.2;
    const double x1 = x0 + width();
    const double h = height();
    const double y0 = jitter ? 1 + wiggle() : 1.0;
    const double y1 = jitter ? 1 + wiggle() : 1.0;
    ring.emplace_back(x1, y1);
    ring.emplace_back(x1 + (jitter ? wiggle() : 0.0), 1 + h);
    ring.emplace_back(x0 + (jitter ? wiggle() : 0.0), 1 + h);
    ring.emplace_back(x0, y0);
  }
  ring.emplace_back(0, 1);
  return ring;
}

/// Thick spiral band (counter-clockwise): centre line r = 1 + theta / (2 pi), width 0.5, over
/// `turns` turns, sampled at randomly jittered angles (about 16 to 24 samples per turn).
inline Ring2d RandomSpiral(double turns, RandomEngine& rng) {
  std::vector<double> thetas = {0.0};
  const double end = 2 * kPi * turns;
  while (thetas.back() + 2 * kPi / 16 < end) {
    thetas.push_back(thetas.back() + UniformReal(rng, 2 * kPi / 24, 2 * kPi / 16));
  }
  thetas.push_back(end);
  Ring2d ring;
  for (double t : thetas) {
    const double r = 1.0 + t / (2 * kPi) + 0.25;
    ring.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  for (auto it = thetas.rbegin(); it != thetas.rend(); ++it) {
    const double r = 1.0 + *it / (2 * kPi) - 0.25;
    ring.emplace_back(r * std::cos(*it), r * std::sin(*it));
  }
  return ring;
}

inline bool ProperlyCross(const Point2d& p, const Point2d& q, const Point2d& a, const Point2d& b) {
  return Orientation(p, q, a) * Orientation(p, q, b) < 0 &&
         Orientation(a, b, p) * Orientation(a, b, q) < 0;
}

/// Random simple polygon (counter-clockwise): random points untangled by 2-opt moves (each move
/// shortens the tour, so it terminates).
inline Ring2d RandomTwoOptPolygon(int n, RandomEngine& rng) {
  Ring2d ring(n);
  for (Point2d& p : ring) {
    const double x = UniformReal(rng, 0.0, 1.0);  // x first: sequenced draws.
    p = Point2d(x, UniformReal(rng, 0.0, 1.0));
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < n && !changed; ++i) {
      for (int j = i + 2; j < n && !changed; ++j) {
        if (i == 0 && j == n - 1) continue;
        if (ProperlyCross(ring[i], ring[i + 1], ring[j], ring[(j + 1) % n])) {
          std::reverse(ring.begin() + i + 1, ring.begin() + j + 1);
          changed = true;
        }
      }
    }
  }
  if (SignedArea(ring) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

/// Whether the direction from ring[i] towards `t` lies in the closed interior wedge at vertex i
/// of the counter-clockwise `ring`.
inline bool InCone(const Ring2d& ring, int i, const Point2d& t) {
  const int n = static_cast<int>(ring.size());
  const Point2d& w = ring[i];
  const Point2d& a = ring[(i + n - 1) % n];
  const Point2d& b = ring[(i + 1) % n];
  const int turn = Orientation(a, w, b);
  if (turn > 0) return Orientation(w, b, t) >= 0 && Orientation(w, a, t) <= 0;
  if (turn < 0) return !(Orientation(w, a, t) > 0 && Orientation(w, b, t) < 0);
  return Orientation(w, b, t) >= 0;  // Straight vertex: the closed left half-plane.
}

/// Whether segment pq lies in the closed polygon of the counter-clockwise `ring` (exactly for
/// vertex end points): no proper crossing with an edge (edge `skip_edge` is ignored), and at
/// every vertex on the segment both directions along it point into the closed interior.
inline bool SegmentInside(const Ring2d& ring, const Point2d& p, const Point2d& q,
                          int skip_edge = -1) {
  const int n = static_cast<int>(ring.size());
  for (int e = 0; e < n; ++e) {
    if (e != skip_edge && ProperlyCross(p, q, ring[e], ring[(e + 1) % n])) return false;
  }
  const Point2d lo = p.cwiseMin(q), hi = p.cwiseMax(q);
  for (int i = 0; i < n; ++i) {
    const Point2d& w = ring[i];
    if (w.x() < lo.x() || w.x() > hi.x() || w.y() < lo.y() || w.y() > hi.y()) continue;
    if (Orientation(p, q, w) != 0) continue;
    if (w != p && !InCone(ring, i, p)) return false;
    if (w != q && !InCone(ring, i, q)) return false;
  }
  return true;
}

/// Dijkstra over the visibility graph from initial distances `dist` (infinity: not a source).
inline std::vector<double> VisibilityDijkstra(const Ring2d& ring, std::vector<double> dist) {
  const int n = static_cast<int>(ring.size());
  std::vector<std::vector<char>> visible(n, std::vector<char>(n, 0));
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      visible[i][j] = visible[j][i] = SegmentInside(ring, ring[i], ring[j]);
    }
  }
  std::vector<char> done(n, 0);
  for (int round = 0; round < n; ++round) {
    int u = -1;
    for (int v = 0; v < n; ++v) {
      if (!done[v] && (u < 0 || dist[v] < dist[u])) u = v;
    }
    done[u] = 1;
    for (int v = 0; v < n; ++v) {
      if (visible[u][v]) dist[v] = std::min(dist[v], dist[u] + (ring[u] - ring[v]).norm());
    }
  }
  return dist;
}

/// Brute-force geodesic distances from vertex `source` of the counter-clockwise `ring`.
inline std::vector<double> BruteForceGeodesic(const Ring2d& ring, int source) {
  std::vector<double> dist(ring.size(), std::numeric_limits<double>::infinity());
  dist[source] = 0.0;
  return VisibilityDijkstra(ring, dist);
}

/// Brute-force distances from every chain vertex to the bridge (chain.back() -> chain.front())
/// inside the pocket polygon: visibility graph plus a perpendicular leg from each vertex to the
/// bridge when that leg stays inside, plus the bridge ends at distance 0.
inline std::vector<double> BruteForceBridgeDistances(const Ring2d& chain) {
  const int m = static_cast<int>(chain.size());
  const bool ccw = SignedArea(chain) > 0;
  Ring2d ring = ccw ? chain : Reversed(chain);
  auto chain_index = [&](int r) { return ccw ? r : m - 1 - r; };
  const int bridge_edge = m - 1;  // ring[m-1] -> ring[0] is the bridge in both orientations.
  const Point2d a = chain.front(), b = chain.back();
  std::vector<double> dist(m, std::numeric_limits<double>::infinity());
  for (int r = 0; r < m; ++r) {
    const int k = chain_index(r);
    if (k == 0 || k == m - 1) {
      dist[r] = 0.0;
      continue;
    }
    const double t = (ring[r] - a).dot(b - a) / (b - a).squaredNorm();
    if (t < 0.0 || t > 1.0) continue;
    const Point2d foot = a + t * (b - a);
    if (SegmentInside(ring, ring[r], foot, bridge_edge)) dist[r] = (ring[r] - foot).norm();
  }
  dist = VisibilityDijkstra(ring, dist);
  std::vector<double> result(m);
  for (int r = 0; r < m; ++r) result[chain_index(r)] = dist[r];
  return result;
}

}  // namespace acdplan::acd::testing
