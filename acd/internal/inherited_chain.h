#pragma once
// The part of a piece's outer ring that copies its parent's.

namespace acdplan::acd::internal {

/// `length` vertices of a piece's outer ring, from position `begin` on, that copy the parent's
/// outer vertices `parent_begin`, `parent_begin` + 1, ... (cyclically, the parent's order). A
/// piece cut by Resolve() has one such chain (its vertices between the cut's ends); its other
/// vertices are new points on edges or vertices of holes.
struct InheritedChain {
  int begin = 0;
  int parent_begin = 0;
  int length = 0;
};

}  // namespace acdplan::acd::internal
