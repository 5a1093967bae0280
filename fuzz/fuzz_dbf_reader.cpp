// libFuzzer target: acd::ReadDbf() on arbitrary bytes, in each encoding, and
// acd::DbfEncodingFromCpg() on them as a .cpg's text. InputError is the expected answer to bad
// input; anything else (another exception, such as nlohmann's on text that is not UTF-8, a
// crash, a sanitizer report, a hang) is a finding.
#include <sstream>
#include <string>
#include <vector>

#include "acd/dbf_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using acdplan::acd::DbfEncoding;
  const std::string text = acdplan::fuzz::InputText(data, size);
  acdplan::acd::DbfEncodingFromCpg(text);
  // Every encoding: each decodes the character fields its own way.
  for (const DbfEncoding encoding :
       {DbfEncoding::kAuto, DbfEncoding::kUtf8, DbfEncoding::kWindows1252, DbfEncoding::kLatin1}) {
    std::istringstream in(text);
    std::vector<std::string> warnings;
    try {
      acdplan::acd::ReadDbf(in, "fuzz.dbf", encoding, &warnings);
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
