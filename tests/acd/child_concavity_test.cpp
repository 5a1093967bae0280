// MeasureChildConcavity() (acd/internal/pocket_cache.h) must give what a full measure of the
// piece gives: Decompose2d() relies on it for every piece it cuts.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "acd/concavity.h"
#include "acd/internal/pocket_cache.h"
#include "acd/internal/resolve.h"
#include "acd/polygon2d.h"
#include "acd/read_polygons.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

void ExpectSameMeasure(const Concavity2d& full, const Concavity2d& child, const std::string& what) {
  EXPECT_EQ(full.hull, child.hull) << what;
  EXPECT_EQ(full.outer, child.outer) << what;
  EXPECT_EQ(full.value, child.value) << what;
  EXPECT_EQ(full.witness_vertex, child.witness_vertex) << what;
  EXPECT_EQ(full.witness_hole, child.witness_hole) << what;
  ASSERT_EQ(full.holes.size(), child.holes.size()) << what;
  for (size_t k = 0; k < full.holes.size(); ++k) {
    EXPECT_EQ(full.holes[k].concavity, child.holes[k].concavity) << what << " hole " << k;
  }
}

// Cuts `polygon` as Decompose2d() does (the witness first, depth first, until convex or
// `max_splits`) and compares each piece's incremental measure with a full one. Returns the
// number of pieces compared.
int CompareAlongDecomposition(const Polygon2d& polygon, const ConcavityOptions& measure,
                              int max_splits) {
  internal::ResolveOptions resolve;
  resolve.concavity_unit = ReferenceRadius(polygon) / 100.0;
  struct Pending {
    Polygon2d piece;
    Concavity2d concavity;
  };
  std::vector<Pending> stack = {{polygon, MeasureConcavity(polygon, measure)}};
  int compared = 0;
  for (int splits = 0; !stack.empty() && splits < max_splits; ++splits) {
    Pending top = std::move(stack.back());
    stack.pop_back();
    if (top.concavity.value == 0.0) continue;
    internal::Resolution resolution;
    if (!internal::Resolve(top.piece, top.concavity, resolve, &resolution)) {
      ADD_FAILURE() << "no cut";
      break;
    }
    std::vector<char> on_hull(top.piece.outer.size(), 0);
    for (const int i : top.concavity.hull) on_hull[i] = 1;
    for (int side = 0; side < 2; ++side) {
      const Polygon2d& piece = resolution.pieces[side];
      EXPECT_EQ(resolution.origin[side].size(), piece.outer.size());
      Concavity2d child = internal::MeasureChildConcavity(piece, resolution.origin[side],
                                                          top.concavity, on_hull, measure, nullptr);
      ExpectSameMeasure(MeasureConcavity(piece, measure), child,
                        "split " + std::to_string(splits) + " side " + std::to_string(side));
      ++compared;
      stack.push_back({piece, std::move(child)});
    }
  }
  return compared;
}

TEST(ChildConcavityTest, EqualsAFullMeasureOnEveryPieceOfRealPolygons) {
  const std::string dir = acdplan::test::DataDir() + "/polygons/acd2d/";
  for (const char* file : {"nazca/nazca_monkey.poly", "neuron/neuron.poly", "hole3.poly",
                           "star/star4_noise.poly", "mammoth.poly"}) {
    std::vector<double> radii;
    const std::vector<Polygon2d> polygons = ReadPolygons(dir + file, &radii);
    for (const ConcavityMeasure m : {ConcavityMeasure::kStraightLine,
                                     ConcavityMeasure::kShortestPath, ConcavityMeasure::kHybrid2}) {
      ConcavityOptions measure;
      measure.measure = m;
      measure.tau = 0.01 * radii.front();
      SCOPED_TRACE(std::string(file) + " measure " + std::to_string(static_cast<int>(m)));
      EXPECT_GT(CompareAlongDecomposition(polygons.front(), measure, 120), 20);
    }
  }
}

TEST(ChildConcavityTest, MeasuresEverythingWhenNothingIsInherited) {
  // A piece that shares no edge with its "parent": every gap is measured.
  const Polygon2d square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  const Polygon2d dented{{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, {}};
  const Concavity2d parent = MeasureConcavity(square);
  const std::vector<char> on_hull(4, 1);
  const Concavity2d child =
      internal::MeasureChildConcavity(dented, {-1, -1, -1, -1, -1}, parent, on_hull, {}, nullptr);
  ExpectSameMeasure(MeasureConcavity(dented), child, "dented");
  EXPECT_GT(child.value, 0.0);
  EXPECT_EQ(child.witness_vertex, 3);
}

TEST(ChildConcavityTest, FallsBackOnAMismatchedOrigin) {
  const Polygon2d dented{{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, {}};
  const Concavity2d parent = MeasureConcavity(dented);
  const std::vector<char> on_hull = {1, 1, 1, 0, 1};
  const Concavity2d child =
      internal::MeasureChildConcavity(dented, {0, 1}, parent, on_hull, {}, nullptr);
  ExpectSameMeasure(parent, child, "same piece");
}

}  // namespace
}  // namespace acdplan::acd
