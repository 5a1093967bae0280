// libFuzzer target: acd::ReadGeoJson() on arbitrary text, refusing and then skipping points and
// lines (GeoJsonSkipOptions). InputError is the expected answer to bad input; anything else
// (another exception, a crash, a sanitizer report, a hang) is a finding.
#include <sstream>
#include <string>
#include <vector>

#include "acd/geojson_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  for (const bool skip : {false, true}) {
    std::istringstream in(text);
    std::vector<std::string> warnings;
    try {
      acdplan::acd::ReadGeoJson(in, "fuzz.geojson", nullptr, nullptr, nullptr, {skip, &warnings});
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
