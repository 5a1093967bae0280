// libFuzzer target: envs::internal::ReadGrayImage() on arbitrary bytes written to a file.
// InputError is the expected answer to bad input; anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding.
#include "base/input_error.h"
#include "envs/internal/gray_image.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      acdplan::fuzz::WriteInputFile("fuzz.img", acdplan::fuzz::InputText(data, size));
  try {
    acdplan::envs::internal::ReadGrayImage(path);
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
