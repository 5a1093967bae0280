#include "acd/concavity_measure.h"

#include <cctype>

#include "acd/input_error.h"

namespace acdplan::acd {

std::string ToString(ConcavityMeasure measure) {
  switch (measure) {
    case ConcavityMeasure::kStraightLine:
      return "sl";
    case ConcavityMeasure::kShortestPath:
      return "sp";
    case ConcavityMeasure::kHybrid1:
      return "h1";
    case ConcavityMeasure::kHybrid2:
      return "h2";
  }
  return "unknown";  // Unreachable for a valid enumerator.
}

ConcavityMeasure ParseConcavityMeasure(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (ConcavityMeasure measure : {ConcavityMeasure::kStraightLine, ConcavityMeasure::kShortestPath,
                                   ConcavityMeasure::kHybrid1, ConcavityMeasure::kHybrid2}) {
    if (lower == ToString(measure)) return measure;
  }
  throw InputError("unknown concavity measure '" + name + "' (expected sl, sp, h1 or h2)");
}

}  // namespace acdplan::acd
