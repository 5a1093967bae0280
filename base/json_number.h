#pragma once
// A measured number in JSON: a figure that could not be measured (NaN) or is unbounded is
// written as null, since JSON has no NaN or infinity.

#include <cmath>
#include <nlohmann/json.hpp>

namespace acdplan {

/// `value` as a JSON number, or null unless it is finite.
inline nlohmann::json JsonNumber(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace acdplan
