#pragma once
// How the messages about a polygon's rings name them (acd/prepare_polygon.h). Internal: include
// only from .cpp files of the acd library.

#include <cstddef>
#include <string>

namespace acdplan::acd::internal {

/// Ring 0 is the "outer ring", ring k + 1 is "hole k" (k the 0-based index among the holes).
inline std::string RingName(size_t ring) {
  return ring == 0 ? "outer ring" : "hole " + std::to_string(ring - 1);
}

}  // namespace acdplan::acd::internal
