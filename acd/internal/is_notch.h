#pragma once
// IsNotch() inline, for the loops that call it on every vertex of a piece (candidate cuts,
// the witness search). Internal: include only from .cpp files of the acd library.

#include <algorithm>
#include <cmath>

#include "acd/internal/exact_predicates.h"
#include "acd/internal/rounding_noise.h"
#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// IsNotch() (acd/concavity.h): the turn prev -> v -> next is clockwise by more than rounding
/// noise, kRoundingNoise times the largest coordinate magnitude (at least 1).
inline bool IsNotchInline(const Point2d& prev, const Point2d& v, const Point2d& next) {
  if (Orientation(prev, v, next) >= 0) return false;
  const Point2d chord = next - prev;
  const double magnitude = std::max({MaxAbs(prev), MaxAbs(v), MaxAbs(next)});
  const double noise = kRoundingNoise * std::max(1.0, magnitude);
  const Point2d offset = v - prev;
  const double cross = chord.x() * offset.y() - chord.y() * offset.x();
  // The same comparison squared, without the square root and the division (this runs for every
  // candidate of every cut): decided when clear of a relative band of 1e-9, far wider than the
  // few ulps either form errs by; inside the band, and where squares could overflow or
  // underflow, the form below decides.
  const double length2 = chord.squaredNorm();
  if (length2 >= 1e-150 && length2 <= 1e150 && std::abs(cross) <= 1e150 && noise <= 1e75) {
    const double lhs = cross * cross, rhs = noise * noise * length2;
    if (lhs > rhs * (1.0 + 1e-9)) return true;
    if (lhs < rhs * (1.0 - 1e-9)) return false;
  }
  const double length = std::sqrt(length2);
  if (length == 0.0) return offset.norm() > noise;  // A spike back onto itself.
  return std::abs(cross) / length > noise;
}

/// IsNotchInline() at vertex `i` of `ring`, between its ring neighbours.
inline bool IsNotchAt(const Ring2d& ring, int i) {
  const int n = static_cast<int>(ring.size());
  return IsNotchInline(ring[i == 0 ? n - 1 : i - 1], ring[i], ring[i + 1 == n ? 0 : i + 1]);
}

}  // namespace acdplan::acd::internal
