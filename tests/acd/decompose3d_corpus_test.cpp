// The 31 V-HACD meshes (data/meshes/vhacd) x tau_rel {0.2, 0.05, 0.02} (tau = tau_rel x
// ReferenceRadius), prepared plain and with repair: every decomposition passes
// CheckDecomposition3d. The surface ACD runs on every prepared mesh (open, non-manifold,
// self-intersecting and solid alike). A sanitizer build takes every fourth mesh.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "acd/check_decomposition3d.h"
#include "acd/internal/surface_acd.h"
#include "acd/prepare_mesh.h"
#include "base/stopwatch.h"
#include "envs/mesh_loader.h"

namespace acdplan::acd {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr size_t kStride = 4;
#else
constexpr size_t kStride = 1;
#endif

std::vector<std::filesystem::path> CorpusFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(ACDPLAN_DATA_DIR) + "/meshes/vhacd")) {
    if (entry.path().extension() == ".obj") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string Problems(const DecompositionCheck& check) {
  std::string all;
  for (const std::string& p : check.problems) all += p + "\n";
  return all;
}

TEST(Decompose3dCorpusTest, SurfaceAcdOfEveryMeshPassesTheCheck) {
  const std::vector<std::filesystem::path> files = CorpusFiles();
  ASSERT_EQ(files.size(), 31u);
  const bool print = std::getenv("ACDPLAN_CORPUS_TABLE") != nullptr;
  for (size_t i = 0; i < files.size(); i += kStride) {
    const std::string name = files[i].filename().string();
    const TriangleMesh mesh = envs::ReadMesh(files[i].string());
    for (const bool repair : {false, true}) {
      PrepareMeshOptions options;
      options.repair = repair;
      const PreparedMesh prepared = PrepareMesh(mesh, options, name);
      const double radius = ReferenceRadius(prepared.mesh);
      for (const double tau_rel : {0.2, 0.05, 0.02}) {
        const double tau = tau_rel * radius;
        const Stopwatch stopwatch;
        const Decomposition3d d = internal::DecomposeSurface(prepared, tau);
        const double seconds = stopwatch.Seconds();
        const Stopwatch check_watch;
        const DecompositionCheck check = CheckDecomposition3d(prepared, d);
        if (print) {
          std::printf("| %s | %s | %zu | %zu | %g | %d | %.3f | %.3f |\n", name.c_str(),
                      repair ? "repair" : "plain", prepared.mesh.triangles.rows() + size_t{0},
                      prepared.parts.size(), tau_rel, d.stats.components, seconds,
                      check_watch.Seconds());
        }
        EXPECT_TRUE(check.ok()) << name << (repair ? " repaired" : "") << " tau_rel " << tau_rel
                                << ":\n"
                                << Problems(check);
        EXPECT_TRUE(d.stats.surface);
        EXPECT_LE(d.stats.max_concavity, tau) << name;
      }
    }
  }
}

}  // namespace
}  // namespace acdplan::acd
