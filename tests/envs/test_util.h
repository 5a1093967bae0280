#pragma once
// Helpers shared by the envs tests: scratch folders, inline fixtures, error messages.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/polygon2d.h"
#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "tests/input_error_of.h"
#include "tests/polygon_fixtures.h"
#include "tests/scratch_dir.h"

namespace acdplan::envs::testing {

/// Tests here say TempDir for the shared scratch folder.
using TempDir = acdplan::test::ScratchDir;

/// The acdplan::InputError message `f()` throws, or "" when it throws nothing.
template <typename F>
std::string ErrorOf(F f) {
  return test::InputErrorOf(f);
}

using test::TotalArea;

/// Every polygon is already clean and valid (PreparePolygon changes nothing), and the set
/// decomposes into convex pieces that CheckDecomposition() accepts.
inline void ExpectValidAndDecomposes(const std::vector<acd::Polygon2d>& polygons) {
  for (size_t k = 0; k < polygons.size(); ++k) {
    const acd::Polygon2d again = acd::PreparePolygon(polygons[k], "polygon " + std::to_string(k));
    EXPECT_EQ(acd::VertexCount(again), acd::VertexCount(polygons[k])) << "polygon " << k;
  }
  const acd::Decomposition2d decomposition = acd::Decompose2d(polygons);
  const acd::DecompositionCheck check = acd::CheckDecomposition(polygons, decomposition);
  EXPECT_TRUE(check.ok()) << (check.ok() ? "" : check.problems.front());
}

}  // namespace acdplan::envs::testing
