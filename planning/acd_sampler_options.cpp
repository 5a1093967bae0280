#include "planning/acd_sampler_options.h"

#include <cmath>

#include "base/enum_names.h"
#include "base/input_error.h"

namespace acdplan::planning {

namespace {

constexpr std::array<EnumName<AcdOrientation>, 2> kOrientations = {{
    {AcdOrientation::kRandom, "random"},
    {AcdOrientation::kAligned, "aligned"},
}};

}  // namespace

AcdOrientation ParseAcdOrientation(const std::string& name) {
  return ValueOf(kOrientations, name, "orientation");
}

std::string ToString(AcdOrientation orientation) { return NameOf(kOrientations, orientation); }

void CheckAcdSamplerOptions(const AcdSamplerOptions& o) {
  auto fail = [](const std::string& field, const std::string& rule, double value) {
    throw InputError("AcdSamplerOptions: " + field + ": expected " + rule + ", got " +
                     std::to_string(value));
  };
  if (!(o.uniform_share >= 0 && o.uniform_share <= 1)) {
    fail("uniform_share", "a number in [0, 1]", o.uniform_share);
  }
  if (!(o.opening_weight >= 0) || !std::isfinite(o.opening_weight)) {
    fail("opening_weight", "a number >= 0", o.opening_weight);
  }
  if (!(o.max_narrowness >= 1) || !std::isfinite(o.max_narrowness)) {
    fail("max_narrowness", "a number >= 1", o.max_narrowness);
  }
  if (!(o.centroid_spread > 0) || !std::isfinite(o.centroid_spread)) {
    fail("centroid_spread", "a number > 0", o.centroid_spread);
  }
  if (!(o.opening_spread > 0) || !std::isfinite(o.opening_spread)) {
    fail("opening_spread", "a number > 0", o.opening_spread);
  }
  if (!std::isfinite(o.long_axis)) fail("long_axis", "a finite angle", o.long_axis);
  if (!(o.aligned_jitter >= 0) || !std::isfinite(o.aligned_jitter)) {
    fail("aligned_jitter", "a number >= 0", o.aligned_jitter);
  }
  if (o.max_attempts < 1) fail("max_attempts", "an integer >= 1", o.max_attempts);
}

}  // namespace acdplan::planning
