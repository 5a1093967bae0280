#pragma once
// A walk over a 3D decomposition's hierarchy tree. Internal.

#include <vector>

#include "acd/decomposition3d.h"

namespace acdplan::acd::internal {

/// The nodes of the subtree of `tree` at `node`, in depth-first pre-order (children in their
/// order): the order the solid ACD numbers its leaves in.
inline std::vector<int> SubtreeDepthFirst(const std::vector<HierarchyNode3d>& tree, int node) {
  std::vector<int> order, stack = {node};
  while (!stack.empty()) {
    const int x = stack.back();
    stack.pop_back();
    order.push_back(x);
    const std::vector<int>& children = tree[static_cast<size_t>(x)].children;
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return order;
}

}  // namespace acdplan::acd::internal
