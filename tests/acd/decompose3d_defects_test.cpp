// Cells of acd3d_bench --check that failed CheckDecomposition3d or missed a target (issue 10),
// each on the corpus mesh that showed the defect (data/meshes/vhacd). Release only: a Debug build
// of the exact kernel takes minutes on them.

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "acd/check_decomposition3d.h"
#include "acd/decompose3d.h"
#include "acd/prepare_mesh.h"
#include "envs/mesh_loader.h"
#include "tests/acd/problem_lines.h"
#include "tests/asan_build.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

// Decomposes the corpus mesh `name` at tau_rel (repaired first when `repair`) and expects the
// check to pass and every component to be within tau.
void ExpectPasses(const std::string& name, double tau_rel, bool repair) {
#ifndef NDEBUG
  GTEST_SKIP() << "Release only";
#endif
  const std::string path = acdplan::test::DataDir() + "/meshes/vhacd/" + name;
  PrepareMeshOptions options;
  options.repair = repair;
  const PreparedMesh prepared = PrepareMesh(envs::ReadMesh(path), options, path);
  ASSERT_TRUE(prepared.solid()) << name;
  const double tau = tau_rel * ReferenceRadius(prepared.mesh);
  const Decomposition3d d = Decompose3d(prepared, {tau, false, 0});
  EXPECT_FALSE(d.stats.surface);
  EXPECT_GT(d.components.size(), 1u);
  EXPECT_LE(d.stats.max_concavity, tau);
  const DecompositionCheck check = CheckDecomposition3d(prepared, d);
  EXPECT_TRUE(check.ok()) << name << " tau_rel " << tau_rel << ":\n"
                          << acdplan::test::ProblemLines(check);
}

// Cut points 1e-17 apart on a needle triangle rounded onto one position: pieces with a
// triangle's two corners at one position, and self-intersecting pieces.
TEST(Decompose3dDefectsTest, DefsphereAtTauRel002RoundsToValidPieces) {
  ExpectPasses("defsphere.obj", 0.02, false);
}

// A hull plane grouped by a sliver facet's own normal cut through the hull, so a face 0.56 deep
// measured 0 ("concavity 0.00036 is below its re-measured lower bound 0.558"); pieces also
// self-intersected after rounding.
TEST(Decompose3dDefectsTest, HoseAtTauRel002MeasuresEveryPieceFromTrueHullPlanes) {
  ExpectPasses("hose.obj", 0.02, false);
}

// The repaired bunny: a stored concavity below the checker's re-measured lower bound.
TEST(Decompose3dDefectsTest, RepairedBunnyAtTauRel005MeasuresEveryPieceFromTrueHullPlanes) {
  ExpectPasses("bunny.obj", 0.05, true);
}

// The surface ACD of the bunny against the dissertation's Table 5 (6 patches at tau_rel 0.2, 97
// at 0.02): without merging adjacent patches whose union is within tau it gave 146 at 0.02.
TEST(Decompose3dDefectsTest, BunnySurfaceHasNoMorePatchesThanTable5) {
#if !defined(NDEBUG) || ACDPLAN_ASAN_BUILD
  // A patch count on a 5,000-triangle mesh (54 s under ASan): the surface ACD's code runs under
  // the sanitizers on the corpus subset (tests/acd/decompose3d_corpus_test.cpp).
  GTEST_SKIP() << "Release only";
#endif
  const std::string path = acdplan::test::DataDir() + "/meshes/vhacd/bunny.obj";
  const PreparedMesh prepared = PrepareMesh(envs::ReadMesh(path), {}, path);
  for (const auto& [tau_rel, table5] : {std::pair<double, size_t>{0.2, 6}, {0.02, 97}}) {
    const double tau = tau_rel * ReferenceRadius(prepared.mesh);
    const Decomposition3d d = Decompose3d(prepared, {tau, true, 0});
    EXPECT_TRUE(d.stats.surface);
    EXPECT_LE(d.components.size(), table5) << "tau_rel " << tau_rel;
    EXPECT_LE(d.stats.max_concavity, tau);
    const DecompositionCheck check = CheckDecomposition3d(prepared, d);
    EXPECT_TRUE(check.ok()) << "tau_rel " << tau_rel << ":\n" << acdplan::test::ProblemLines(check);
  }
}

}  // namespace
}  // namespace acdplan::acd
