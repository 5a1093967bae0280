#pragma once
// An adjacency graph as one sorted set of neighbours per node, as the merge passes of the solid
// and the surface ACD keep it.

#include <set>
#include <vector>

namespace acdplan::acd::internal {

/// Contracts the edge a-b of `neighbours`: b's neighbours become a's, and b has none left.
inline void ContractInto(int a, int b, std::vector<std::set<int>>* neighbours) {
  std::vector<std::set<int>>& n = *neighbours;
  for (int c : n[static_cast<size_t>(b)]) {
    n[static_cast<size_t>(c)].erase(b);
    if (c != a) {
      n[static_cast<size_t>(c)].insert(a);
      n[static_cast<size_t>(a)].insert(c);
    }
  }
  n[static_cast<size_t>(b)].clear();
  n[static_cast<size_t>(a)].erase(b);
}

}  // namespace acdplan::acd::internal
