#include "acd/internal/separate_pinches.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <map>

#include "acd/internal/disjoint_sets.h"

namespace acdplan::acd::internal {
namespace {

// How far the copies of a pinch vertex move, relative to the shortest edge at it.
constexpr double kPinchShift = 1e-3;
constexpr double kMinShiftUlps = 16;

// One fan around a pinch vertex: its faces and the centroid of their corners.
struct Fan {
  std::vector<int> members;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  bool faces_out = true;  // Its triangles face away from the centroid: the solid is in its cone.
};

// The sign of the volume that fan `faces` closes with the cone from its rim to `apex`: the
// triangles face out of that cone when it is positive. Differences are scaled to the fan's
// size first, so that coordinates near 1e300 do not overflow.
bool FacesOutOfCone(const std::vector<Eigen::Vector3d>& vertices,
                    const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& faces,
                    const Eigen::Vector3d& apex) {
  double size = 0;
  for (const int f : faces) {
    for (const int w : triangles[static_cast<size_t>(f)]) {
      size = std::max(size, (vertices[static_cast<size_t>(w)] - apex).cwiseAbs().maxCoeff());
    }
  }
  if (!(size > 0)) return true;
  double volume = 0;
  for (const int f : faces) {
    const auto& t = triangles[static_cast<size_t>(f)];
    const Eigen::Vector3d a = (vertices[static_cast<size_t>(t[0])] - apex) / size;
    const Eigen::Vector3d b = (vertices[static_cast<size_t>(t[1])] - apex) / size;
    const Eigen::Vector3d c = (vertices[static_cast<size_t>(t[2])] - apex) / size;
    volume += a.dot(b.cross(c));
  }
  return volume >= 0;
}

// Calls visit(v, faces, only) for each vertex v < vertex_count and each group's faces at v
// (ascending; groups in ascending order), `only` true when that group has all of v's faces.
// The faces at each vertex are listed before the first call: visit may renumber corners.
template <class Visit>
void ForEachGroupAtVertex(const std::vector<std::array<int, 3>>& triangles, size_t vertex_count,
                          const std::vector<int>& group, Visit visit) {
  std::vector<std::vector<int>> around(vertex_count);
  for (size_t f = 0; f < triangles.size(); ++f) {
    for (const int v : triangles[f]) around[static_cast<size_t>(v)].push_back(static_cast<int>(f));
  }
  auto group_of = [&](int f) { return group.empty() ? 0 : group[static_cast<size_t>(f)]; };
  std::vector<int> run;
  for (size_t v = 0; v < vertex_count; ++v) {
    std::vector<int>& faces = around[v];
    std::stable_sort(faces.begin(), faces.end(),
                     [&](int f, int g) { return group_of(f) < group_of(g); });
    for (size_t begin = 0, end = 0; begin < faces.size(); begin = end) {
      while (end < faces.size() && group_of(faces[end]) == group_of(faces[begin])) ++end;
      run.assign(faces.begin() + static_cast<std::ptrdiff_t>(begin),
                 faces.begin() + static_cast<std::ptrdiff_t>(end));
      visit(static_cast<int>(v), run, end == faces.size() && begin == 0);
    }
  }
}

}  // namespace

int FansAroundVertex(const std::vector<std::array<int, 3>>& triangles,
                     const std::vector<int>& faces, int v, std::vector<int>* fan) {
  DisjointSets joined(static_cast<int>(faces.size()));
  std::map<int, int> by_neighbour;  // the other end of an edge through v -> a face using it
  for (size_t i = 0; i < faces.size(); ++i) {
    for (const int w : triangles[static_cast<size_t>(faces[i])]) {
      if (w == v) continue;
      const auto [it, inserted] = by_neighbour.emplace(w, static_cast<int>(i));
      if (!inserted) joined.Unite(it->second, static_cast<int>(i));
    }
  }
  // A set's name is its lowest member, met first.
  std::vector<int> number(faces.size(), -1);
  int count = 0;
  fan->resize(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    int& n = number[static_cast<size_t>(joined.Find(static_cast<int>(i)))];
    if (n < 0) n = count++;
    (*fan)[i] = n;
  }
  return count;
}

PinchSeparation SeparatePinches(std::vector<Eigen::Vector3d>* vertices,
                                std::vector<std::array<int, 3>>* triangles,
                                const std::vector<int>& group) {
  PinchSeparation out;
  int counted = -1;  // The last vertex counted as separated or left.
  std::vector<int> fan_of;
  ForEachGroupAtVertex(
      *triangles, vertices->size(), group,
      [&](int v, const std::vector<int>& run, bool only_group) {
        std::vector<Fan> fans(static_cast<size_t>(FansAroundVertex(*triangles, run, v, &fan_of)));
        if (fans.size() < 2) return;
        for (size_t i = 0; i < run.size(); ++i) {
          fans[static_cast<size_t>(fan_of[i])].members.push_back(run[i]);
        }
        const Eigen::Vector3d pinch = (*vertices)[static_cast<size_t>(v)];
        double shortest = std::numeric_limits<double>::infinity();
        bool both_kinds = false;
        for (Fan& fan : fans) {
          for (const int f : fan.members) {
            for (const int w : (*triangles)[static_cast<size_t>(f)]) {
              fan.centroid += (*vertices)[static_cast<size_t>(w)];
              if (w != v)
                shortest = std::min(shortest, ((*vertices)[static_cast<size_t>(w)] - pinch).norm());
            }
          }
          fan.centroid /= 3.0 * static_cast<double>(fan.members.size());
          fan.faces_out = FacesOutOfCone(*vertices, *triangles, fan.members, fan.centroid);
          both_kinds = both_kinds || fan.faces_out != fans.front().faces_out;
        }
        const double shift = kPinchShift * shortest;
        const double ulp = pinch.cwiseAbs().maxCoeff() * std::numeric_limits<double>::epsilon();
        if (!(shift >= kMinShiftUlps * ulp)) {
          if (counted != v) ++out.left;
          counted = v;
          return;
        }
        if (counted != v) ++out.separated;
        counted = v;
        // v itself goes to the fan that stays, or else (when no other group uses it) to the first.
        bool v_taken = both_kinds || !only_group;
        bool kept = false;
        for (Fan& fan : fans) {
          int copy = v;
          if (both_kinds && fan.faces_out && !kept) {
            kept = true;
          } else {
            const Eigen::Vector3d direction = fan.centroid - pinch;
            const double norm = direction.norm();
            const Eigen::Vector3d moved =
                norm > 0 ? Eigen::Vector3d(pinch + (shift / norm) * direction) : pinch;
            if (v_taken) {
              copy = static_cast<int>(vertices->size());
              vertices->push_back(moved);
            } else {
              (*vertices)[static_cast<size_t>(v)] = moved;
              v_taken = true;
            }
          }
          for (const int f : fan.members) {
            for (int& w : (*triangles)[static_cast<size_t>(f)]) {
              if (w == v) w = copy;
            }
          }
        }
      });
  return out;
}

int CountPinches(const std::vector<std::array<int, 3>>& triangles, size_t vertex_count,
                 const std::vector<int>& group, int* first, int* fans_at_first) {
  int count = 0, counted = -1;
  *first = -1;
  std::vector<int> fan;
  ForEachGroupAtVertex(triangles, vertex_count, group,
                       [&](int v, const std::vector<int>& run, bool) {
                         const int fans = FansAroundVertex(triangles, run, v, &fan);
                         if (fans < 2 || counted == v) return;
                         counted = v;
                         ++count;
                         if (*first < 0) *first = v, *fans_at_first = fans;
                       });
  return count;
}

}  // namespace acdplan::acd::internal
