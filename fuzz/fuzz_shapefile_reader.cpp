// libFuzzer target: acd::ReadShapefile() on arbitrary bytes. InputError is the expected answer
// to bad input; anything else (another exception, a crash, a sanitizer report, a hang) is a
// finding.
#include <sstream>

#include "acd/shapefile_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(acdplan::fuzz::InputText(data, size));
  std::vector<int> multipolygons;
  std::vector<std::string> warnings;
  try {
    acdplan::acd::ReadShapefile(in, "fuzz.shp", &multipolygons, &warnings);
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
