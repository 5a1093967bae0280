// Decomposes an L-shaped room with the installed acdplan::acd alone and checks the result.
#include <cstdio>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/prepare_polygon.h"

int main() {
  namespace acd = acdplan::acd;
  const acd::Polygon2d room =
      acd::PreparePolygon({{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}}, {}}, "room");
  const acd::Decomposition2d d = acd::Decompose2d(room);
  const acd::DecompositionCheck check =
      acd::CheckDecomposition(std::vector<acd::Polygon2d>{room}, d);
  std::printf("acdplan::acd consumer: %zu components, check %s\n", d.components.size(),
              check.ok() ? "ok" : "failed");
  return check.ok() && d.components.size() == 2 ? 0 : 1;
}
