#pragma once
// Reuse of pocket concavities across the pieces of one decomposition.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "acd/concavity.h"
#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Per-vertex concavities of pockets already measured, keyed by the pocket chain. A cut only
/// changes the pockets it touches; every other pocket of a child piece is a pocket of its parent
/// with the same chain and bridge, so its SP distances (a triangulation and a funnel walk) are
/// looked up instead of recomputed. One cache serves one decomposition (fixed measure and tau).
class PocketCache {
 public:
  /// The stored distances for `chain`, or nullptr.
  const std::vector<double>* Find(const Ring2d& chain) const;
  /// Stores `distances` for `chain`.
  void Insert(const Ring2d& chain, std::vector<double> distances);

 private:
  struct Entry {
    Ring2d chain;
    std::vector<double> distances;
  };
  static std::uint64_t Hash(const Ring2d& chain);
  std::unordered_multimap<std::uint64_t, Entry> entries_;
};

/// MeasureConcavity() that reuses and fills `cache` (may be nullptr).
Concavity2d MeasureConcavityCached(const Polygon2d& polygon, const ConcavityOptions& options,
                                   PocketCache* cache);

}  // namespace acdplan::acd::internal
