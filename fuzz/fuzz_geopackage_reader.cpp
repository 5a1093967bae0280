// libFuzzer target: acd::ReadGeoPackageBytes() on arbitrary bytes, read as a GeoPackage (an
// SQLite database image) with its attributes and with points and lines skipped, as `acdplan
// decompose` reads one. InputError is the expected answer to bad input; anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#include "acd/geopackage_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    acdplan::acd::ReadGeoPackageBytes(acdplan::fuzz::InputText(data, size), "fuzz.gpkg", "",
                                      /*skip_non_areal=*/true, /*with_properties=*/true);
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
