#pragma once
// Disjoint sets (union-find) over 0..n-1, each set named by its lowest member.

#include <algorithm>
#include <numeric>
#include <vector>

namespace acdplan::acd::internal {

/// Union-find with path halving. Unite keeps the lower root, so a set's name (Find) is its
/// lowest member whatever order the unions come in: labels built from it are deterministic.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int Find(int x) {
    while (parent_[static_cast<size_t>(x)] != x) {
      parent_[static_cast<size_t>(x)] =
          parent_[static_cast<size_t>(parent_[static_cast<size_t>(x)])];
      x = parent_[static_cast<size_t>(x)];
    }
    return x;
  }
  void Unite(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace acdplan::acd::internal
