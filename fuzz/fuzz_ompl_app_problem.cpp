// libFuzzer target: planning::LoadScenarioFile() on arbitrary bytes written to an OMPL.app
// problem file (`.cfg`, envs::ReadOmplAppProblem(), then planning::ScenarioFromOmplApp()).
// Three small meshes are written beside it, so that inputs naming them (the seeds do) reach
// the robot centre, the footprints and the workspace, not only the parser. InputError is the
// expected answer to bad input; anything else (another exception, a crash, a sanitizer report,
// a hang) is a finding.
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"
#include "planning/scenario_cfg.h"

namespace {

// A planar quadrilateral robot (z = 0), two boxes standing on z = 0 (a 2D world), and a closed
// square pyramid (a 3D robot).
constexpr const char* kPlateRobot = "v 0 0 0\nv 4 0 0\nv 4 1 0\nv 0 3 0\nf 1 2 3 4\n";
constexpr const char* kWalls =
    "v 2 0 0\nv 3 0 0\nv 3 4 0\nv 2 4 0\nv 2 0 1\nv 3 0 1\nv 3 4 1\nv 2 4 1\n"
    "v 5 2 0\nv 6 2 0\nv 6 6 0\nv 5 6 0\nv 5 2 1\nv 6 2 1\nv 6 6 1\nv 5 6 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    "f 9 12 11 10\nf 13 14 15 16\nf 9 10 14 13\nf 10 11 15 14\nf 11 12 16 15\nf 12 9 13 16\n";
constexpr const char* kPyramidRobot =
    "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 0 0 4\n"
    "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool meshes_written = [] {
    acdplan::fuzz::WriteInputFile("plate.obj", kPlateRobot);
    acdplan::fuzz::WriteInputFile("walls.obj", kWalls);
    acdplan::fuzz::WriteInputFile("pyramid.obj", kPyramidRobot);
    return true;
  }();
  (void)meshes_written;
  const std::string path =
      acdplan::fuzz::WriteInputFile("fuzz.cfg", acdplan::fuzz::InputText(data, size));
  try {
    acdplan::planning::LoadScenarioFile(path);
  } catch (const acdplan::InputError&) {
  }
  return 0;
}
