// libFuzzer target: a small triangle mesh decoded from the input goes through PrepareMesh()
// (cleaning, orientation, the exact defect diagnosis and, when the input asks, the repair:
// hole filling and the exact winding union), then, as `acdplan decompose` does, the solid
// ACD when the prepared mesh is a solid, else the surface ACD, and the result must pass
// CheckDecomposition3d(). InputError is the expected answer to a mesh PrepareMesh() refuses;
// anything else (another exception, a failed check, a crash, a sanitizer report, a hang) is a
// finding.
//
// The encoding keeps meshes small and their coordinates on a coarse lattice, where coplanar
// faces, shared edges, touching and crossing shells (the cases exact predicates decide) are
// common: byte 0 holds the options (bit 0: repair; bits 1-2: tau_rel 0.02, 0.05, 0.1, 0.2;
// bits 3-4: the lattice's spacing 1/4, 1e-6, 1e6 or 1e30, as meshes come in any unit), byte 1
// the vertex count (4 + byte % 13), then three signed bytes per vertex (a coordinate is the
// byte times the spacing), then three bytes per triangle (indices modulo the vertex count), at most
// 48 triangles. The 3D code carries no libFuzzer coverage (it would slow the sanitizer tree's
// 3D tests), so this explores by mutating the seeds rather than by coverage.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/check_decomposition3d.h"
#include "acd/decompose3d.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"

namespace {

constexpr int kMaxTriangles = 48;
constexpr double kTauRel[] = {0.02, 0.05, 0.1, 0.2};
constexpr double kSpacing[] = {0.25, 1e-6, 1e6, 1e30};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acdplan::acd;
  if (size < 2) return 0;
  const int vertex_count = 4 + data[1] % 13;
  std::size_t at = 2;
  if (size < at + 3 * static_cast<std::size_t>(vertex_count) + 3) return 0;
  const double spacing = kSpacing[(data[0] >> 3) & 3];
  std::vector<Eigen::Vector3d> vertices;
  for (int v = 0; v < vertex_count; ++v, at += 3) {
    vertices.emplace_back(static_cast<std::int8_t>(data[at]) * spacing,
                          static_cast<std::int8_t>(data[at + 1]) * spacing,
                          static_cast<std::int8_t>(data[at + 2]) * spacing);
  }
  std::vector<Eigen::Vector3i> triangles;
  for (; at + 3 <= size && triangles.size() < kMaxTriangles; at += 3) {
    triangles.emplace_back(data[at] % vertex_count, data[at + 1] % vertex_count,
                           data[at + 2] % vertex_count);
  }
  PrepareMeshOptions prepare;
  prepare.repair = (data[0] & 1) != 0;
  PreparedMesh prepared;
  try {
    prepared = PrepareMesh(MakeTriangleMesh(vertices, triangles), prepare, "fuzz");
  } catch (const acdplan::InputError&) {
    return 0;
  }
  Decompose3dOptions options;
  options.tau = kTauRel[(data[0] >> 1) & 3] * ReferenceRadius(prepared.mesh);
  options.surface = !prepared.solid();
  const DecompositionCheck check = CheckDecomposition3d(prepared, Decompose3d(prepared, options));
  if (!check.ok()) {
    for (const std::string& problem : check.problems) std::fprintf(stderr, "%s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
