// libFuzzer target: acd::ReadPoly() on arbitrary text, with and without a warnings list (extra
// chains are read, or are an error). InputError is the expected answer to bad input; anything
// else (another exception, a crash, a sanitizer report, a hang) is a finding.
#include <sstream>

#include "acd/poly_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  for (bool with_warnings : {true, false}) {
    std::istringstream in(text);
    std::vector<std::string> warnings;
    try {
      acdplan::acd::ReadPoly(in, "fuzz.poly", with_warnings ? &warnings : nullptr);
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
