#include "acd/decomposition3d.h"

#include <algorithm>

namespace acdplan::acd {

std::vector<std::vector<int>> ComponentGraph(const Decomposition3d& decomposition) {
  std::vector<std::vector<int>> graph(decomposition.components.size());
  const int n = static_cast<int>(graph.size());
  for (const Opening3d& o : decomposition.openings) {
    if (o.component_a < 0 || o.component_b < 0 || o.component_a >= n || o.component_b >= n ||
        o.component_a == o.component_b) {
      continue;
    }
    graph[static_cast<size_t>(o.component_a)].push_back(o.component_b);
    graph[static_cast<size_t>(o.component_b)].push_back(o.component_a);
  }
  for (auto& neighbours : graph) {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  }
  return graph;
}

}  // namespace acdplan::acd
