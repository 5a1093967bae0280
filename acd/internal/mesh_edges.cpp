#include "acd/internal/mesh_edges.h"

#include <algorithm>
#include <tuple>

namespace acdplan::acd::internal {

EdgeTable BuildEdgeTable(const TriangleMesh& mesh) {
  struct Entry {
    int a, b, face, corner;
  };
  const int n = static_cast<int>(mesh.triangles.rows());
  std::vector<Entry> entries;
  entries.reserve(3 * static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles(f, k), v = mesh.triangles(f, (k + 1) % 3);
      entries.push_back({std::min(u, v), std::max(u, v), f, k});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return std::tie(x.a, x.b, x.face, x.corner) < std::tie(y.a, y.b, y.face, y.corner);
  });
  EdgeTable table;
  table.face_edges.resize(static_cast<size_t>(n));
  table.faces.reserve(entries.size());
  for (size_t i = 0; i < entries.size(); ++i) {
    const Entry& e = entries[i];
    if (table.edges.empty() || table.edges.back().a != e.a || table.edges.back().b != e.b) {
      table.edges.push_back({e.a, e.b, static_cast<int>(i), 0});
    }
    ++table.edges.back().count;
    table.faces.push_back(e.face);
    table.face_edges[static_cast<size_t>(e.face)][static_cast<size_t>(e.corner)] =
        static_cast<int>(table.edges.size()) - 1;
  }
  return table;
}

bool RunsForward(const TriangleMesh& mesh, int f, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    if (mesh.triangles(f, k) == a) return mesh.triangles(f, (k + 1) % 3) == b;
  }
  return false;
}

}  // namespace acdplan::acd::internal
