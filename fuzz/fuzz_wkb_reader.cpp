// libFuzzer target: acd::ReadWkb() on arbitrary bytes (the geometries of GeoPackage layers).
// InputError is the expected answer to bad input; anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding.
#include "acd/wkb_reader.h"
#include "base/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    acdplan::acd::ReadWkb(data, size, "fuzz");
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
