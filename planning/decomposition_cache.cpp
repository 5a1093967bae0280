#include "planning/decomposition_cache.h"

#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "base/stopwatch.h"
#include "envs/free_space2d.h"

namespace acdplan::planning {

namespace {

/// The whole content of the map and the options, as 64-bit words: an exact key (no hash
/// collisions to reason about). Doubles are taken bit for bit.
std::vector<std::uint64_t> Key(const envs::Workspace2d& workspace,
                               const acd::Decompose2dOptions& options) {
  std::vector<std::uint64_t> key;
  auto add = [&key](double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    key.push_back(bits);
  };
  auto add_ring = [&](const acd::Ring2d& ring) {
    key.push_back(ring.size());
    for (const acd::Point2d& p : ring) add(p.x()), add(p.y());
  };
  add(options.tau);
  key.push_back(static_cast<std::uint64_t>(options.measure));
  key.push_back(static_cast<std::uint64_t>(options.hole_diameter));
  add(options.min_convexity);
  add(options.score_concavity);
  add(options.score_distance);
  key.push_back(options.steiner_cuts ? 1 : 0);
  add(workspace.bounds.min().x()), add(workspace.bounds.min().y());
  add(workspace.bounds.max().x()), add(workspace.bounds.max().y());
  key.push_back(workspace.obstacles.size());
  for (const acd::Polygon2d& obstacle : workspace.obstacles) {
    add_ring(obstacle.outer);
    key.push_back(obstacle.holes.size());
    for (const acd::Ring2d& hole : obstacle.holes) add_ring(hole);
  }
  return key;
}

struct Cache {
  std::mutex mutex;
  std::map<std::vector<std::uint64_t>, CachedDecomposition> entries;
};

Cache& TheCache() {
  static Cache* cache = new Cache();  // Never destroyed: usable from any static destructor.
  return *cache;
}

}  // namespace

CachedDecomposition DecomposeFreeSpaceCached(const envs::Workspace2d& workspace,
                                             const acd::Decompose2dOptions& options) {
  std::vector<std::uint64_t> key = Key(workspace, options);
  Cache& cache = TheCache();
  {
    std::lock_guard<std::mutex> lock(cache.mutex);
    auto it = cache.entries.find(key);
    if (it != cache.entries.end()) {
      CachedDecomposition hit = it->second;
      hit.hit = true;
      return hit;
    }
  }
  // Computed outside the lock; two threads missing at once both compute, the first stores.
  const Stopwatch stopwatch;
  CachedDecomposition entry;
  entry.decomposition = std::make_shared<const acd::Decomposition2d>(
      acd::Decompose2d(envs::FreeSpace2d(workspace), options));
  entry.compute_ms = stopwatch.Milliseconds();
  std::lock_guard<std::mutex> lock(cache.mutex);
  return cache.entries.emplace(std::move(key), entry).first->second;
}

void ClearDecompositionCache() {
  Cache& cache = TheCache();
  std::lock_guard<std::mutex> lock(cache.mutex);
  cache.entries.clear();
}

}  // namespace acdplan::planning
