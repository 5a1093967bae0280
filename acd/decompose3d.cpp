#include "acd/decompose3d.h"

#include <cmath>
#include <sstream>

#include "acd/internal/solid_acd.h"
#include "acd/internal/surface_acd.h"
#include "base/input_error.h"
#include "base/stopwatch.h"

namespace acdplan::acd {
namespace {

void ValidateOptions(const Decompose3dOptions& options, const PreparedMesh& prepared) {
  auto fail = [](const std::string& what) { throw InputError("Decompose3d(): " + what); };
  if (!(options.tau >= 0.0) || !std::isfinite(options.tau)) {
    std::ostringstream s;
    s << "tau must be a finite number >= 0, got " << options.tau;
    fail(s.str());
  }
  if (options.max_hulls < 0) {
    fail("max_hulls must be >= 0 (0 = no cap), got " + std::to_string(options.max_hulls));
  }
  if (options.merge_growth && std::isnan(*options.merge_growth)) {
    fail("merge_growth must be a number (< 0: no merging)");
  }
  if (prepared.parts.empty()) fail("the prepared mesh has no part (run PrepareMesh first)");
}

}  // namespace

Decomposition3d Decompose3d(const PreparedMesh& prepared, const Decompose3dOptions& options) {
  ValidateOptions(options, prepared);
  const Stopwatch watch;
  const bool surface = options.surface || !prepared.solid();
  double merge_growth = -1.0;
  if (!surface) {
    if (options.merge_growth) {
      merge_growth = *options.merge_growth;
    } else {
      const double radius = ReferenceRadius(prepared.mesh);
      merge_growth = radius > 0 ? kMergeGrowthPerTauRel * options.tau / radius : 0.0;
    }
  }
  Decomposition3d out = surface ? internal::DecomposeSurface(prepared, options.tau)
                                : internal::DecomposeSolid(prepared, options.tau, options.max_hulls,
                                                           options.feature_grouping, merge_growth);
  out.tau = options.tau;
  out.max_hulls = options.max_hulls;
  out.merge_growth = merge_growth;
  out.stats.surface = surface;
  out.stats.time_ms = watch.Milliseconds();
  return out;
}

}  // namespace acdplan::acd
