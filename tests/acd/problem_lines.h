#pragma once
// The problems a decomposition check found, one per line: what a failing test prints.

#include <string>

#include "acd/check_decomposition.h"

namespace acdplan::test {

/// Every line of `check.problems`, each ended by a newline ("" when the check passed).
inline std::string ProblemLines(const acd::DecompositionCheck& check) {
  std::string all;
  for (const std::string& line : check.problems) all += line + "\n";
  return all;
}

}  // namespace acdplan::test
