#pragma once
// How `acdplan decompose --check` reports a decomposition that fails its check (2D and 3D).

#include <string>

#include "acd/check_decomposition.h"

namespace acdplan::tools {

/// Prints "internal error: the decomposition of <input> failed its check" and every problem
/// on stderr, and returns exit status 1 (a bug of ours, not bad input). Nothing is written.
int ReportFailedCheck(const std::string& input, const acd::DecompositionCheck& check);

}  // namespace acdplan::tools
