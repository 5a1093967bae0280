// libFuzzer target: acd::ReadGeoJson() on arbitrary text. InputError is the expected answer to bad
// input; anything else (another exception, a crash, a sanitizer report, a hang) is a finding.
#include <sstream>

#include "acd/geojson_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(acdplan::fuzz::InputText(data, size));
  try {
    acdplan::acd::ReadGeoJson(in, "fuzz.geojson");
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
