#pragma once
// Splitting a closed boundary that passes through a point several times into simple loops.
// Internal (also used by envs/, whose free-space boundaries come from CGAL's polygon sets).

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

namespace acdplan::acd::internal {

/// `cycle`, a closed sequence of points that may pass through a point several times (a
/// boundary touching itself, as CGAL's "relatively simple" polygons and arrangement faces do),
/// split into loops that pass each point once: whenever a point repeats, the stretch walked
/// since its first visit is a loop of its own, and the point stays for the rest. Loops of fewer
/// than 3 points are dropped. O(n log n), points compared with `Less` (exact points: exactly).
template <typename Point, typename Less = std::less<Point>>
std::vector<std::vector<Point>> SplitAtRepeats(const std::vector<Point>& cycle) {
  std::vector<std::vector<Point>> loops;
  std::vector<Point> stack;
  std::map<Point, size_t, Less> at;  // Where each point on the stack is.
  auto keep = [&loops](std::vector<Point> loop) {
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  };
  for (const Point& p : cycle) {
    const auto seen = at.find(p);
    if (seen == at.end()) {
      at.emplace(p, stack.size());
      stack.push_back(p);
      continue;
    }
    const size_t first = seen->second;
    for (size_t k = first + 1; k < stack.size(); ++k) at.erase(stack[k]);
    keep(std::vector<Point>(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end()));
    stack.resize(first + 1);
  }
  keep(std::move(stack));
  return loops;
}

}  // namespace acdplan::acd::internal
