#pragma once
// Nesting levels of the faces of a CGAL constrained triangulation. Internal: include only from
// .cpp files (CGAL types in the interface).

#include <list>

namespace acdplan::acd::internal {

/// Sets `info().nesting` of every face of `cdt` to the number of constrained edges a walk from
/// the infinite face must cross to reach it, so that the faces at odd levels are inside the
/// region the constraints bound (the flood fill of CGAL's "polygon with holes" triangulation
/// example). `Cdt` is a CGAL constrained triangulation whose face info has an int `nesting`.
/// Regions are flooded level by level (the constrained edges met wait in a FIFO queue), so a
/// face gets the least crossing count. O(faces).
template <typename Cdt>
void MarkNestingLevels(Cdt& cdt) {
  for (auto f : cdt.all_face_handles()) f->info().nesting = -1;
  std::list<typename Cdt::Edge> frontier;  // Constrained edges out of flooded faces.
  auto flood = [&](typename Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1) return;
    std::list<typename Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      typename Cdt::Face_handle f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1) continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        typename Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(typename Cdt::Edge(f, i))) {
          frontier.emplace_back(f, i);
        } else {
          queue.push_back(n);
        }
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!frontier.empty()) {
    const typename Cdt::Edge e = frontier.front();
    frontier.pop_front();
    typename Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
}

}  // namespace acdplan::acd::internal
