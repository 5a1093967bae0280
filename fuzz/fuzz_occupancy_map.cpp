// libFuzzer target: envs::ReadOccupancyMap() on a map YAML and its image. The input is the
// YAML text, a NUL byte, then the image's bytes (written to "map.img" beside the YAML, which
// the seeds' `image:` names); without a NUL the image is empty. Both UnknownCells modes are
// read. InputError is the expected answer to bad input; anything else (another exception, a
// crash, a sanitizer report, a hang) is a finding.
#include "base/input_error.h"
#include "envs/occupancy_map.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  const std::size_t nul = text.find('\0');
  acdplan::fuzz::WriteInputFile("map.img",
                                nul == std::string::npos ? std::string() : text.substr(nul + 1));
  const std::string yaml = acdplan::fuzz::WriteInputFile("map.yaml", text.substr(0, nul));
  for (auto unknown : {acdplan::envs::UnknownCells::kBlocked, acdplan::envs::UnknownCells::kFree}) {
    try {
      acdplan::envs::ReadOccupancyMap(yaml, {unknown});
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
