#include "acd/concavity_measure.h"

#include <cctype>

#include "base/enum_names.h"

namespace acdplan::acd {
namespace {

constexpr std::array<EnumName<ConcavityMeasure>, 4> kMeasures = {{
    {ConcavityMeasure::kStraightLine, "sl"},
    {ConcavityMeasure::kShortestPath, "sp"},
    {ConcavityMeasure::kHybrid1, "h1"},
    {ConcavityMeasure::kHybrid2, "h2"},
}};

constexpr std::array<EnumName<HoleDiameter>, 3> kHoleDiameters = {{
    {HoleDiameter::kAuto, "auto"},
    {HoleDiameter::kPrincipalAxis, "pa"},
    {HoleDiameter::kGeodesic, "geodesic"},
}};

}  // namespace

std::string ToString(ConcavityMeasure measure) { return NameOf(kMeasures, measure); }

ConcavityMeasure ParseConcavityMeasure(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  try {
    return ValueOf(kMeasures, lower, "concavity measure");
  } catch (const InputError&) {
    throw InputError(UnknownName("concavity measure", name, NamesOf(kMeasures)));
  }
}

std::string ToString(HoleDiameter diameter) { return NameOf(kHoleDiameters, diameter); }

HoleDiameter ParseHoleDiameter(const std::string& name) {
  return ValueOf(kHoleDiameters, name, "hole diameter");
}

}  // namespace acdplan::acd
