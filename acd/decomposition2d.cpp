#include "acd/decomposition2d.h"

#include <algorithm>
#include <stdexcept>

namespace acdplan::acd {

std::vector<std::vector<int>> ComponentGraph(const Decomposition2d& decomposition) {
  const int n = static_cast<int>(decomposition.components.size());
  std::vector<std::vector<int>> graph(n);
  for (size_t k = 0; k < decomposition.openings.size(); ++k) {
    const Opening2d& opening = decomposition.openings[k];
    const int a = opening.component_a;
    const int b = opening.component_b;
    if (a < 0 || a >= n || b < 0 || b >= n || a == b) {
      throw std::invalid_argument("ComponentGraph(): opening " + std::to_string(k) +
                                  " joins components " + std::to_string(a) + " and " +
                                  std::to_string(b) + ", but there are " + std::to_string(n) +
                                  " components");
    }
    graph[a].push_back(b);
    graph[b].push_back(a);
  }
  // Two components may share several openings (a cut through a hole meets the same
  // neighbour twice); the graph lists each neighbour once.
  for (std::vector<int>& neighbours : graph) {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  }
  return graph;
}

}  // namespace acdplan::acd
