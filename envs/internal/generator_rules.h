#pragma once
// What the 2D and 3D world generators share: their argument checks and how a description
// prints a length.

#include <cmath>
#include <string>

#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::envs::internal {

/// Throws InputError "where: rule" unless `ok`.
inline void Require(bool ok, const char* where, const std::string& rule) {
  if (!ok) throw InputError(std::string(where) + ": " + rule);
}

/// A finite length or count greater than zero.
inline bool Positive(double value) { return std::isfinite(value) && value > 0.0; }

/// Lengths in descriptions, as a stream prints them ("0.5", "1e-05").
inline std::string Format(double value) { return FormatSignificant(value, 6); }

}  // namespace acdplan::envs::internal
