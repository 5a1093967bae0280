// libFuzzer target: envs::LoadWorkspace2dYaml() on arbitrary bytes written to a file. InputError is
// the expected answer to bad input; anything else (another exception, a crash, a sanitizer report,
// a hang) is a finding.
#include "base/input_error.h"
#include "envs/workspace_yaml.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      acdplan::fuzz::WriteInputFile("fuzz.yaml", acdplan::fuzz::InputText(data, size));
  try {
    acdplan::envs::LoadWorkspace2dYaml(path);
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
