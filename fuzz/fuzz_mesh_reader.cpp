// libFuzzer target: envs::ReadObj(), ReadOff(), ReadPly() and ReadStl() on arbitrary bytes.
// InputError is the expected answer to bad input; anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding. A mesh read must pass CheckTriangleMesh() (indices in
// range, finite coordinates) and keep only vertices a triangle uses.
#include <cstdlib>
#include <sstream>
#include <vector>

#include "base/input_error.h"
#include "envs/obj_off_reader.h"
#include "envs/ply_reader.h"
#include "envs/stl_reader.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  for (const int format : {0, 1, 2}) {
    std::istringstream in(text);
    try {
      const acdplan::acd::TriangleMesh mesh = format == 0 ? acdplan::envs::ReadObj(in, "fuzz.obj")
                                              : format == 1
                                                  ? acdplan::envs::ReadOff(in, "fuzz.off")
                                                  : acdplan::envs::ReadPly(in, "fuzz.ply");
      acdplan::acd::CheckTriangleMesh(mesh, "fuzz");
      std::vector<char> used(static_cast<size_t>(mesh.vertices.rows()), 0);
      for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
        for (int c = 0; c < 3; ++c) used[static_cast<size_t>(mesh.triangles(t, c))] = 1;
      }
      for (const char u : used) {
        if (u == 0) std::abort();  // An unused vertex was kept.
      }
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
