// MeasureChildConcavity() (acd/internal/pocket_cache.h) must give what a full measure of the
// piece gives: Decompose2d() relies on it for every piece it cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acd/concavity.h"
#include "acd/internal/pocket_cache.h"
#include "acd/internal/resolve.h"
#include "acd/internal/ring_locator.h"
#include "acd/polygon2d.h"
#include "acd/read_polygons.h"
#include "base/random.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

void ExpectSameMeasure(const Concavity2d& full, const Concavity2d& child, const std::string& what) {
  EXPECT_EQ(full.hull, child.hull) << what;
  EXPECT_EQ(full.bridge_max, child.bridge_max) << what;
  EXPECT_EQ(full.outer, child.outer) << what;
  EXPECT_EQ(full.value, child.value) << what;
  EXPECT_EQ(full.witness_vertex, child.witness_vertex) << what;
  EXPECT_EQ(full.witness_hole, child.witness_hole) << what;
  ASSERT_EQ(full.holes.size(), child.holes.size()) << what;
  for (size_t k = 0; k < full.holes.size(); ++k) {
    EXPECT_EQ(full.holes[k].p, child.holes[k].p) << what << " hole " << k;
    EXPECT_EQ(full.holes[k].cw_p, child.holes[k].cw_p) << what << " hole " << k;
    EXPECT_EQ(full.holes[k].diameter, child.holes[k].diameter) << what << " hole " << k;
    EXPECT_EQ(full.holes[k].depth, child.holes[k].depth) << what << " hole " << k;
    EXPECT_EQ(full.holes[k].concavity, child.holes[k].concavity) << what << " hole " << k;
  }
}

// Cuts `polygon` as Decompose2d() does (the witness first, depth first, until convex or
// `max_splits`) and compares each piece's incremental measure, which inherits the parent's hole
// searches, with a full one. Returns the number of pieces compared.
int CompareAlongDecomposition(const Polygon2d& polygon, const ConcavityOptions& measure,
                              int max_splits) {
  internal::ResolveOptions resolve;
  resolve.concavity_unit = ReferenceRadius(polygon) / 100.0;
  struct Pending {
    Polygon2d piece;
    Concavity2d concavity;
    std::vector<internal::HoleNeighbours> neighbours;
  };
  std::vector<Pending> stack(1);
  stack[0].piece = polygon;
  stack[0].concavity =
      internal::MeasureConcavityCached(polygon, measure, nullptr, &stack[0].neighbours);
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
    for (int side = 0; side < 2; ++side) {
      const Polygon2d& piece = resolution.pieces[side];
      const internal::InheritedChain& chain = resolution.inherited[side];
      // The chain copies what it says it copies.
      EXPECT_LE(chain.begin + chain.length, static_cast<int>(piece.outer.size()));
      for (int k = 0; k < chain.length && chain.begin + k < static_cast<int>(piece.outer.size());
           ++k) {
        const int from = (chain.parent_begin + k) % static_cast<int>(top.piece.outer.size());
        EXPECT_EQ(piece.outer[chain.begin + k], top.piece.outer[from]) << "split " << splits;
      }
      // Its edges lie where the resolution says: the first outer_count on the parent's outer
      // edges from first_outer_edge on (inner vertices copied, ends on those edges), those
      // listed on the cuts (end to end), the others on the parent's holes.
      const internal::PieceEdges& edges = resolution.edges[side];
      const int n = static_cast<int>(piece.outer.size());
      const int parent_n = static_cast<int>(top.piece.outer.size());
      auto vertex = [&](int i) { return piece.outer[i % n]; };
      for (int t = 0; t < edges.outer_count; ++t) {
        const Point2d& u = top.piece.outer[(edges.first_outer_edge + t) % parent_n];
        const Point2d& w = top.piece.outer[(edges.first_outer_edge + t + 1) % parent_n];
        for (const Point2d& p : {vertex(t), vertex(t + 1)}) {
          EXPECT_LE(internal::SegmentDistance(p, u, w), 1e-12 * ReferenceRadius(top.piece))
              << "split " << splits << " side " << side << " edge " << t;
        }
      }
      std::vector<bool> on_cut(n, false);
      for (const auto& [edge, cut] : edges.cuts) {
        if (cut >= static_cast<int>(resolution.cuts.size())) {
          ADD_FAILURE() << "no cut " << cut;
          continue;
        }
        const Cut2d& c = resolution.cuts[cut];
        const bool along = vertex(edge) == c.from && vertex(edge + 1) == c.to;
        const bool against = vertex(edge) == c.to && vertex(edge + 1) == c.from;
        EXPECT_TRUE(along || against) << "split " << splits << " side " << side << " edge " << edge;
        on_cut[edge] = true;
      }
      for (int i = edges.outer_count; i < n; ++i) {
        if (on_cut[i]) continue;
        bool on_hole = false;
        for (const Ring2d& hole : top.piece.holes) {
          for (size_t j = 0; j < hole.size() && !on_hole; ++j) {
            on_hole = hole[j] == vertex(i) && hole[(j + 1) % hole.size()] == vertex(i + 1);
          }
        }
        EXPECT_TRUE(on_hole) << "split " << splits << " side " << side << " edge " << i;
      }
      // So do the holes.
      const std::vector<int>& origins = resolution.hole_origins[side];
      EXPECT_EQ(origins.size(), piece.holes.size());
      for (size_t k = 0; k < origins.size() && k < piece.holes.size(); ++k) {
        const bool known = origins[k] < static_cast<int>(top.piece.holes.size());
        EXPECT_TRUE(known) << "split " << splits;
        if (known) {
          EXPECT_EQ(piece.holes[k], top.piece.holes[origins[k]]) << "split " << splits;
        }
      }
      std::vector<internal::HoleNeighbours> neighbours;
      Concavity2d child = internal::MeasureChildConcavity(piece, chain, top.piece.outer,
                                                          top.concavity, measure, nullptr, nullptr,
                                                          {&top.neighbours, &origins}, &neighbours);
      ExpectSameMeasure(MeasureConcavity(piece, measure), child,
                        "split " + std::to_string(splits) + " side " + std::to_string(side));
      ++compared;
      stack.push_back({piece, std::move(child), std::move(neighbours)});
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

// Holes in exact rows and columns, as on grid maps and in clipped tiles: an antipode lies as
// near to several vertices of the outer ring or of other holes, which is where a piece may
// order them differently from its parent. Square holes on an integer lattice, and the same
// lattice with the holes' corners jittered (ties only in places), under a saw-tooth edge.
TEST(ChildConcavityTest, InheritedHoleSearchesEqualFreshOnesOnLatticesOfHoles) {
  for (const double jitter : {0.0, 0.3}) {
    RandomEngine rng(11);
    auto wiggle = [&] { return jitter * static_cast<double>(UniformIndex(rng, 9)) / 8.0; };
    Polygon2d polygon;
    polygon.outer = {{0, 0}, {36, 0}};
    for (int i = 0; i <= 12; ++i) polygon.outer.emplace_back(36 - 3 * i, i % 2 == 0 ? 36 : 37);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const double x = 6 * i + 2, y = 6 * j + 2;
        // Clockwise.
        polygon.holes.push_back({{x + wiggle(), y + wiggle()},
                                 {x + wiggle(), y + 2 + wiggle()},
                                 {x + 2 + wiggle(), y + 2 + wiggle()},
                                 {x + 2 + wiggle(), y + wiggle()}});
      }
    }
    for (const ConcavityMeasure m : {ConcavityMeasure::kStraightLine,
                                     ConcavityMeasure::kShortestPath, ConcavityMeasure::kHybrid2}) {
      ConcavityOptions measure;
      measure.measure = m;
      measure.tau = 0.01 * ReferenceRadius(polygon);
      SCOPED_TRACE("jitter " + std::to_string(jitter) + " measure " +
                   std::to_string(static_cast<int>(m)));
      EXPECT_GT(CompareAlongDecomposition(polygon, measure, 200), 60);
    }
  }
}

// A parent measured by SL with the searches behind its holes' links, which the pieces below
// inherit.
struct MeasuredParent {
  Polygon2d polygon;
  Concavity2d concavity;
  std::vector<internal::HoleNeighbours> neighbours;
};

ConcavityOptions StraightLine() {
  ConcavityOptions measure;
  measure.measure = ConcavityMeasure::kStraightLine;
  return measure;
}

MeasuredParent MeasureParent(const Polygon2d& polygon) {
  MeasuredParent parent{polygon, {}, {}};
  parent.concavity =
      internal::MeasureConcavityCached(polygon, StraightLine(), nullptr, &parent.neighbours);
  return parent;
}

// The measure of `piece` (whose holes are the parent's `origins`) that inherits from `parent`,
// checked against a full one.
Concavity2d MeasureChild(const MeasuredParent& parent, const Polygon2d& piece,
                         const internal::InheritedChain& chain, const std::vector<int>& origins) {
  const Concavity2d child = internal::MeasureChildConcavity(
      piece, chain, parent.polygon.outer, parent.concavity, StraightLine(), nullptr, nullptr,
      {&parent.neighbours, &origins});
  ExpectSameMeasure(MeasureConcavity(piece, StraightLine()), child, "piece");
  return child;
}

// An antipode of a hole, (3, 5), lies 5 from two outer vertices: the parent's 0, on its hull,
// and 2, a notch. The parent links to vertex 0, the lower index; the piece copies both, but
// its ring starts at the notch, so it links there, and the hole sits deeper by the notch's
// concavity. The tie must send the piece to a search of its own.
TEST(ChildConcavityTest, AntipodeAsNearToTwoOuterVerticesOfTheParent) {
  const MeasuredParent parent =
      MeasureParent({{{0, 1}, {1, -3}, {3, 0}, {5, -3}, {12, -3}, {12, 10}, {0, 10}},
                     {{{3, 5}, {5, 5.2}, {7, 5}, {5, 4.8}}}});
  EXPECT_EQ(parent.concavity.holes.at(0).depth, 5.0);
  // The cut from notch 2 to (0.5, -1) on the edge 0 -> 1; the piece copies parent vertices
  // 2 ... 6, 0.
  const Polygon2d piece{{{3, 0}, {5, -3}, {12, -3}, {12, 10}, {0, 10}, {0, 1}, {0.5, -1}},
                        parent.polygon.holes};
  const Concavity2d child = MeasureChild(parent, piece, {0, 2, 6}, {0});
  EXPECT_EQ(child.holes.at(0).depth, child.outer[0] + 5.0);
  EXPECT_GT(child.outer[0], 0.0);
}

// Hole 0's antipode (10, 5) lies 1 from the parent's spike tip (10, 4) and 1.5 from hole 1:
// the parent links it to the tip, and its search, bounded by 1, saw no hole. The piece loses the
// tip; its nearest outer vertices lie 5.1 away, so hole 1 is now the nearer, which the parent's
// search could not know.
TEST(ChildConcavityTest, AHoleNearerThanTheOuterVertexTheCutRemoved) {
  const MeasuredParent parent = MeasureParent(
      {{{0, 0}, {9, 0}, {10, 4}, {11, 0}, {20, 0}, {20, 10}, {0, 10}},
       {{{10, 5}, {12, 5.2}, {14, 5}, {12, 4.8}}, {{5, 5}, {6.75, 5.2}, {8.5, 5}, {6.75, 4.8}}}});
  // The cut (9, 0) - (11, 0) takes off the spike; the piece copies parent vertices 3 ... 6, 0, 1.
  const Polygon2d piece{{{11, 0}, {20, 0}, {20, 10}, {0, 10}, {0, 0}, {9, 0}},
                        parent.polygon.holes};
  const Concavity2d child = MeasureChild(parent, piece, {0, 3, 6}, {0, 1});
  EXPECT_EQ(child.holes.at(0).depth, child.holes.at(1).concavity + 1.5);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-cut-end-outside-parent-
// hull.poly): a cut ending on the parent's hull edge next to a hull vertex whose angle is nearly
// flat; the end, rounded, lay outside the parent's hull, so that vertex was no strict hull
// vertex of the piece, and the inherited gaps were put on the wrong hull edges (a component of
// H1-concavity 1.75 accepted at tau 0.76).
TEST(ChildConcavityTest, CutEndRoundedOutOfTheParentsHull) {
  ReadPolygonsOptions repair;
  repair.repair = true;
  const std::vector<Polygon2d> polygons =
      ReadPolygons(acdplan::test::SourceDir() +
                       "/fuzz/corpus/decompose2d/regression-cut-end-outside-parent-hull.poly",
                   nullptr, repair);
  ASSERT_EQ(polygons.size(), 13u);
  for (const ConcavityMeasure m : {ConcavityMeasure::kStraightLine, ConcavityMeasure::kShortestPath,
                                   ConcavityMeasure::kHybrid1, ConcavityMeasure::kHybrid2}) {
    for (const Polygon2d& polygon : polygons) {
      ConcavityOptions measure;
      measure.measure = m;
      measure.tau = 0.05 * ReferenceRadius(polygon);
      SCOPED_TRACE("measure " + std::to_string(static_cast<int>(m)));
      CompareAlongDecomposition(polygon, measure, 50);
    }
  }
}

// A cut end rounded just outside a single hull edge of the parent, clear of the edges beside
// it: the hull grows by a sliver and every parent hull vertex stays strict, so the parent's
// measure is reused, and must still equal a full measure. The parent: a rectangle with a pocket
// in its bottom edge (notch 2); the cut runs from the notch up to the top hull edge, at a point
// one ulp above it.
TEST(ChildConcavityTest, CutEndJustOutsideOneHullEdge) {
  const Polygon2d parent_polygon{{{0, 0}, {2, 0}, {3, 2}, {4, 0}, {6, 0}, {6, 4}, {0, 4}}, {}};
  const Concavity2d parent = MeasureConcavity(parent_polygon);
  ASSERT_EQ(parent.hull, (std::vector<int>{0, 4, 5, 6}));
  const Point2d end(3.0, std::nextafter(4.0, 5.0));
  // Right: parent vertices 2 ... 5, then the end. Left: the end, then parent vertices 6, 0, 1, 2.
  const Polygon2d right{{{3, 2}, {4, 0}, {6, 0}, {6, 4}, end}, {}};
  const Polygon2d left{{end, {0, 4}, {0, 0}, {2, 0}, {3, 2}}, {}};
  ExpectSameMeasure(
      MeasureConcavity(right),
      internal::MeasureChildConcavity(right, {0, 2, 4}, parent_polygon.outer, parent, {}, nullptr),
      "right piece");
  ExpectSameMeasure(
      MeasureConcavity(left),
      internal::MeasureChildConcavity(left, {1, 6, 4}, parent_polygon.outer, parent, {}, nullptr),
      "left piece");
}

TEST(ChildConcavityTest, MeasuresEverythingWhenNothingIsInherited) {
  // A piece that shares no edge with its "parent": every gap is measured.
  const Polygon2d square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  const Polygon2d dented{{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, {}};
  const Concavity2d parent = MeasureConcavity(square);
  const Concavity2d child =
      internal::MeasureChildConcavity(dented, {}, square.outer, parent, {}, nullptr);
  ExpectSameMeasure(MeasureConcavity(dented), child, "dented");
  EXPECT_GT(child.value, 0.0);
  EXPECT_EQ(child.witness_vertex, 3);
}

TEST(ChildConcavityTest, FallsBackOnAChainThatDoesNotFit) {
  const Polygon2d dented{{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, {}};
  const Concavity2d parent = MeasureConcavity(dented);
  for (const internal::InheritedChain chain :
       {internal::InheritedChain{3, 0, 3}, internal::InheritedChain{0, 5, 3},
        internal::InheritedChain{0, 0, 6}, internal::InheritedChain{-1, 0, 2}}) {
    const Concavity2d child =
        internal::MeasureChildConcavity(dented, chain, dented.outer, parent, {}, nullptr);
    ExpectSameMeasure(parent, child, "same piece");
  }
}

TEST(ChildConcavityTest, InheritsTheGapsBetweenParentHullVertices) {
  // Two pockets under the parent's hull edges (6, 3) -> (4, 4) and (2, 4) -> (0, 3.5), at
  // vertices 3 and 6. The left piece of the cut from notch 3 down to (5, 0) keeps the second
  // pocket whole (parent vertices 3 ... 7, 0 are its vertices 0 ... 5: the chain wraps past the
  // parent's vertex 7), so vertex 6's concavity is copied, not measured.
  const Polygon2d parent_polygon{{{0, 0}, {6, 0}, {6, 3}, {5, 1}, {4, 4}, {2, 4}, {1, 2}, {0, 3.5}},
                                 {}};
  const Concavity2d parent = MeasureConcavity(parent_polygon);
  ASSERT_EQ(parent.hull, (std::vector<int>{0, 1, 2, 4, 5, 7}));
  const Polygon2d piece{{{5, 1}, {4, 4}, {2, 4}, {1, 2}, {0, 3.5}, {0, 0}, {5, 0}}, {}};
  const Concavity2d child =
      internal::MeasureChildConcavity(piece, {0, 3, 6}, parent_polygon.outer, parent, {}, nullptr);
  ExpectSameMeasure(MeasureConcavity(piece), child, "left piece");
  EXPECT_EQ(child.witness_vertex, 3);
  EXPECT_EQ(child.value, parent.outer[6]);
}

}  // namespace
}  // namespace acdplan::acd
