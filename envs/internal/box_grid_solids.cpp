#include "envs/internal/box_grid_solids.h"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace acdplan::envs::internal {
namespace {

void SortUnique(std::vector<double>* values) {
  std::sort(values->begin(), values->end());
  values->erase(std::unique(values->begin(), values->end()), values->end());
}

}  // namespace

std::vector<acd::TriangleMesh> BoxGridSolids(
    std::vector<double> x, std::vector<double> y, std::vector<double> z,
    const std::function<bool(const Eigen::Vector3d&)>& solid) {
  SortUnique(&x);
  SortUnique(&y);
  SortUnique(&z);
  const std::array<int, 3> n = {static_cast<int>(x.size()) - 1, static_cast<int>(y.size()) - 1,
                                static_cast<int>(z.size()) - 1};
  std::vector<acd::TriangleMesh> parts;
  if (n[0] < 1 || n[1] < 1 || n[2] < 1) return parts;
  auto cell_index = [&n](const std::array<int, 3>& c) {
    return (static_cast<size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0];
  };
  const size_t cells = static_cast<size_t>(n[0]) * n[1] * n[2];
  std::vector<char> occupied(cells, 0);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const Eigen::Vector3d centre((x[i] + x[i + 1]) / 2, (y[j] + y[j + 1]) / 2,
                                     (z[k] + z[k + 1]) / 2);
        occupied[cell_index({i, j, k})] = solid(centre) ? 1 : 0;
      }
    }
  }
  auto is_solid = [&](const std::array<int, 3>& c) {
    for (int a = 0; a < 3; ++a) {
      if (c[a] < 0 || c[a] >= n[a]) return false;
    }
    return occupied[cell_index(c)] != 0;
  };

  std::vector<int> part_of(cells, -1);
  for (size_t start = 0; start < cells; ++start) {
    if (!occupied[start] || part_of[start] >= 0) continue;
    const int part = static_cast<int>(parts.size());
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3i> triangles;
    std::unordered_map<size_t, int> vertex_of;  // grid point -> index in `vertices`
    auto vertex = [&](const std::array<int, 3>& p) {
      const size_t key = (static_cast<size_t>(p[2]) * (n[1] + 1) + p[1]) * (n[0] + 1) + p[0];
      const auto [it, inserted] = vertex_of.emplace(key, static_cast<int>(vertices.size()));
      if (inserted) vertices.emplace_back(x[p[0]], y[p[1]], z[p[2]]);
      return it->second;
    };
    std::vector<std::array<int, 3>> stack = {
        {static_cast<int>(start % n[0]), static_cast<int>(start / n[0] % n[1]),
         static_cast<int>(start / (static_cast<size_t>(n[0]) * n[1]))}};
    part_of[start] = part;
    while (!stack.empty()) {
      const std::array<int, 3> c = stack.back();
      stack.pop_back();
      for (int a = 0; a < 3; ++a) {
        for (int side : {0, 1}) {
          std::array<int, 3> next = c;
          next[a] += side ? 1 : -1;
          if (is_solid(next)) {
            const size_t id = cell_index(next);
            if (part_of[id] < 0) {
              part_of[id] = part;
              stack.push_back(next);
            }
            continue;
          }
          // A boundary face: its corners on the plane of axis `a`, ordered so that the
          // normal e_b x e_c = e_a points out on side 1 and is reversed on side 0.
          const int b = (a + 1) % 3, d = (a + 2) % 3;
          std::array<std::array<int, 3>, 4> corner;
          for (std::array<int, 3>& p : corner) {
            p = c;
            p[a] += side;
          }
          corner[1][b] += 1;
          corner[2][b] += 1;
          corner[2][d] += 1;
          corner[3][d] += 1;
          std::array<int, 4> v = {vertex(corner[0]), vertex(corner[1]), vertex(corner[2]),
                                  vertex(corner[3])};
          if (!side) std::swap(v[1], v[3]);
          triangles.emplace_back(v[0], v[1], v[2]);
          triangles.emplace_back(v[0], v[2], v[3]);
        }
      }
    }
    parts.push_back(acd::MakeTriangleMesh(vertices, triangles));
  }
  return parts;
}

}  // namespace acdplan::envs::internal
