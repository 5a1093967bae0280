// libFuzzer target: acd::ReadKml() on arbitrary bytes, with points and lines skipped and the
// attributes kept, as `acdplan decompose` reads a file; bytes that start as a zip archive does
// are also read as a KMZ (acd::ReadKmzRoot(), through a file). InputError is the expected answer
// to bad input; anything else (another exception, a crash, a sanitizer report, a hang) is a
// finding.
#include <sstream>

#include "acd/kml_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  std::istringstream in(text);
  acdplan::acd::KmlExtras extras;
  try {
    acdplan::acd::ReadKml(in, "fuzz.kml", /*skip_non_areal=*/true, &extras);
  } catch (const acdplan::InputError&) {
  }
  if (text.compare(0, 4, "PK\x03\x04") == 0) {
    try {
      std::istringstream root(
          acdplan::acd::ReadKmzRoot(acdplan::fuzz::WriteInputFile("fuzz.kmz", text), nullptr));
      acdplan::acd::ReadKml(root, "fuzz.kmz/doc.kml", /*skip_non_areal=*/true, &extras);
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
