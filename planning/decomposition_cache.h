#pragma once
// The ACD of a map, computed once per process and reused by every later query on it.

#include <memory>

#include "acd/decompose2d.h"
#include "acd/decomposition2d.h"
#include "envs/workspace2d.h"

namespace acdplan::planning {

/// A decomposition from DecomposeFreeSpaceCached().
struct CachedDecomposition {
  std::shared_ptr<const acd::Decomposition2d> decomposition;  ///< Never null; immutable.
  double compute_ms = 0.0;  ///< What computing it cost (free space + ACD), when it was computed.
  bool hit = false;         ///< True if it came from the cache (this call computed nothing).
};

/// The ACD of `workspace`'s free space (envs::FreeSpace2d, then acd::Decompose2d with
/// `options`), from an in-process cache keyed by the workspace's content (bounds and every
/// obstacle coordinate, bit for bit) and every field of `options`; computed and stored on a
/// miss. A decomposition is a property of the map: repeated queries on one map (the runs of
/// `acdplan bench`, whose children inherit the parent's warmed cache through fork()) pay for
/// it once, and still report its cost (`compute_ms`). Thread-safe; entries are never evicted
/// (one per distinct map and options: a few kB to MB each).
CachedDecomposition DecomposeFreeSpaceCached(const envs::Workspace2d& workspace,
                                             const acd::Decompose2dOptions& options);

/// Empties the cache (tests; a process that plans on many one-off maps).
void ClearDecompositionCache();

}  // namespace acdplan::planning
