#pragma once
// The concavity measures of dissertation Ch. IV.A.

#include <string>

namespace acdplan::acd {

/// How the concavity of an outer-boundary vertex is measured (Ch. IV.A.1).
enum class ConcavityMeasure {
  kStraightLine,  ///< SL: straight-line distance to the pocket's bridge (IV.A.1.a).
  kShortestPath,  ///< SP: shortest path inside the pocket polygon to the bridge (Algorithm 2).
  kHybrid1,       ///< H1: SL unless the pocket has an edge facing away from its bridge (Alg. 3).
  kHybrid2,       ///< H2: SL; SP only where SL stays within tau and a hazard exists (Alg. 4).
};

/// How a hole's antipodal pair p, cw(p) is estimated (Ch. IV.A.2.b, Eqn. 4.2).
enum class HoleDiameter {
  kAuto,           ///< Principal axis for SL and H2, geodesic for SP and H1 (the text's advice).
  kPrincipalAxis,  ///< Extreme vertices along the principal axis; Euclidean distance (Eqn. 4.1).
  kGeodesic,       ///< Geodesic diameter of the hole by two shortest-path sweeps; immune to the
                   ///< arbitrarily large error of the principal axis on winding holes (Fig. 20).
};

/// "sl", "sp", "h1", "h2".
std::string ToString(ConcavityMeasure measure);

/// Parses "sl" | "sp" | "h1" | "h2" (case-insensitive).
/// @throws InputError "unknown concavity measure '<name>' (expected one of: sl, sp, h1, h2)".
ConcavityMeasure ParseConcavityMeasure(const std::string& name);

/// "auto", "pa", "geodesic".
std::string ToString(HoleDiameter diameter);

/// Parses "auto" | "pa" | "geodesic".
/// @throws InputError "unknown hole diameter '<name>' (expected one of: auto, pa, geodesic)".
HoleDiameter ParseHoleDiameter(const std::string& name);

}  // namespace acdplan::acd
