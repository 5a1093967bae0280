// Temporary: the surface ACD (acd/internal/surface_acd.cpp) is written on another branch; this
// stand-in keeps the library linking until it is merged, and is deleted at the merge.
#include <stdexcept>

#include "acd/internal/surface_acd.h"

namespace acdplan::acd::internal {

Decomposition3d DecomposeSurface(const PreparedMesh& /*prepared*/, double /*tau*/) {
  throw std::logic_error("surface ACD pending merge");
}

}  // namespace acdplan::acd::internal
