// libFuzzer target: bench::LoadBenchSpec() and bench::LoadTargetsFile() (with the vocabulary
// of every benchmark) on arbitrary bytes written to a file. InputError is the expected answer
// to bad input; anything else (another exception, a crash, a sanitizer report, a hang) is a
// finding.
#include "base/input_error.h"
#include "bench/acd_bench.h"
#include "bench/collision_bench.h"
#include "bench/spec.h"
#include "bench/summary.h"
#include "bench/targets.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      acdplan::fuzz::WriteInputFile("fuzz.yaml", acdplan::fuzz::InputText(data, size));
  try {
    acdplan::bench::LoadBenchSpec(path);
  } catch (const acdplan::InputError&) {
  }
  for (const acdplan::bench::TargetVocabulary* vocabulary :
       {&acdplan::bench::PlanningTargetVocabulary(), &acdplan::bench::AcdBenchTargetVocabulary(),
        &acdplan::bench::CollisionTargetVocabulary()}) {
    try {
      acdplan::bench::LoadTargetsFile(path, *vocabulary);
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
