#pragma once
// Reuse of pocket concavities across the pieces of one decomposition.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "acd/concavity.h"
#include "acd/internal/hole_neighbours.h"
#include "acd/internal/inherited_chain.h"
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

/// MeasureConcavity() that reuses and fills `cache` (may be nullptr). `neighbours` (unless
/// nullptr) receives the searches behind the holes' links, for the pieces' measures.
Concavity2d MeasureConcavityCached(const Polygon2d& polygon, const ConcavityOptions& options,
                                   PocketCache* cache,
                                   std::vector<HoleNeighbours>* neighbours = nullptr);

/// MeasureConcavityCached() of a piece cut from a measured parent, the same result for less work:
/// `chain` is the part of the piece's outer ring that copies the parent's (`parent_ring`, whose
/// measure is `parent`). Hull gaps of the parent on the chain keep their vertices' concavity and
/// stay hull gaps of the piece, so only the gaps next to the cuts are measured again and the
/// hull is built over the other vertices. `spare`: a measure no longer needed, or nullptr; the
/// result takes over its storage (it is left empty). `holes`: the parent's hole searches, which
/// the piece's take over where they stand; `neighbours` as for MeasureConcavityCached().
Concavity2d MeasureChildConcavity(const Polygon2d& piece, const InheritedChain& chain,
                                  const Ring2d& parent_ring, const Concavity2d& parent,
                                  const ConcavityOptions& options, PocketCache* cache,
                                  Concavity2d* spare = nullptr, const InheritedHoles& holes = {},
                                  std::vector<HoleNeighbours>* neighbours = nullptr);

}  // namespace acdplan::acd::internal
