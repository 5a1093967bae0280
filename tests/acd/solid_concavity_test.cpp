#include "acd/internal/solid_concavity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

// The L-block's notch corner (1, 1) lies 1/sqrt(2) below the hull's slanted facet x + y = 3.
TEST(MeasureSolidConcavity, TheLBlockIsAsDeepAsItsNotchCorner) {
  const SolidConcavity c = MeasureSolidConcavity(test::LBlock(), 0.1);
  EXPECT_NEAR(c.value, std::sqrt(0.5), 1e-9);
  EXPECT_GE(c.witness_vertex, 0);
  EXPECT_NEAR(c.witness.x(), 1.0, 1e-12);
  EXPECT_NEAR(c.witness.y(), 1.0, 1e-12);
}

// A needle (the L-profile 1e-4 across, 1 long) has a hull volume below kInPlaneTolerance x its
// size cubed, as a flat plate has, but it is not flat: its notch is 7e-5 deep, far above the
// in-plane tolerance of 1.4e-6. Judged flat by its hull volume, it was measured 0 and failed
// CheckDecomposition3d's re-measure (ob_chair_gothic, tau_rel 0.05, a sliver of a cut).
TEST(MeasureSolidConcavity, ANeedleIsNotFlat) {
  const double s = 1e-4;
  const TriangleMesh needle =
      test::Extrude({{0, 0}, {2 * s, 0}, {2 * s, s}, {s, s}, {s, 2 * s}, {0, 2 * s}}, 1.0);
  EXPECT_NEAR(MeasureSolidConcavity(needle, 1e-5).value, std::sqrt(0.5) * s, 1e-9);
}

// A plate within the in-plane tolerance of one plane is flat, whatever its outline.
TEST(MeasureSolidConcavity, APlateThinnerThanTheToleranceIsFlat) {
  const TriangleMesh plate = test::Extrude({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1e-8);
  EXPECT_EQ(MeasureSolidConcavity(plate, 0.1).value, 0.0);
}

}  // namespace
}  // namespace acdplan::acd::internal
