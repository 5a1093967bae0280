// Property tests of Decompose2d() on the whole acd2d corpus: every .poly file under
// data/polygons/acd2d (found at run time) x the four concavity measures x
// tau_rel in {0, 0.005, 0.01, 0.05, 0.1}; each decomposition must pass CheckDecomposition()
// (components tile the input, are simple, and are tau-convex under the measure used).
// bird.poly, shipped broken, must be rejected with its documented message; simple5.poly, which
// declares fewer chains than it holds, is read whole (with a warning) and is a case like any.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/concavity.h"
#include "acd/decompose2d.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/read_polygons.h"
#include "base/input_error.h"
#include "tests/asan_build.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using acdplan::test::kAcd2d;

constexpr double kTauRel[] = {0.0, 0.005, 0.01, 0.05, 0.1};
constexpr ConcavityMeasure kMeasures[] = {ConcavityMeasure::kStraightLine,
                                          ConcavityMeasure::kShortestPath,
                                          ConcavityMeasure::kHybrid1, ConcavityMeasure::kHybrid2};

// Files the corpus ships with a defect; each has its own test below, not a property case.
bool IsKnownBroken(const std::string& name) { return name == "bird.poly"; }

struct PropertyCase {
  std::string path;      // Absolute path of the .poly file.
  std::string relative;  // Path under acd2d, for messages.
  ConcavityMeasure measure;
  double tau_rel;
};

// GoogleTest prints the parameter of a failed case with this.
void PrintTo(const PropertyCase& c, std::ostream* os) {
  *os << c.relative << " " << ToString(c.measure) << " tau_rel " << c.tau_rel;
}

std::vector<std::string> PolygonCorpusFiles() {
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kAcd2d)) {
    if (entry.is_regular_file() && entry.path().extension() == ".poly") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());  // Directory order is unspecified; names must be stable.
  return files;
}

// Every corpus file (but the broken one) x measure x tau_rel: 53 x 4 x 5 = 1060 cases, about
// 120 s with ASan+UBSan. The sanitizer build runs a fifth of them, every file under every
// measure once, at a tau_rel that turns with the file and the measure (so each tau_rel still
// meets each measure and the large files at tau_rel 0); the Release suite runs them all.
std::vector<PropertyCase> PropertyCases() {
  constexpr int kTauCount = static_cast<int>(std::size(kTauRel));
  std::vector<PropertyCase> cases;
  int file_index = 0;
  for (const std::string& path : PolygonCorpusFiles()) {
    if (IsKnownBroken(fs::path(path).filename().string())) continue;
    for (int m = 0; m < static_cast<int>(std::size(kMeasures)); ++m) {
      for (int t = 0; t < kTauCount; ++t) {
        if (ACDPLAN_ASAN_BUILD && t != (file_index + m) % kTauCount) continue;
        cases.push_back({path, fs::relative(path, kAcd2d).string(), kMeasures[m], kTauRel[t]});
      }
    }
    ++file_index;
  }
  return cases;
}

// "nazca_nazca_monkey_sp_tau0_005": letters, digits and '_' only (GoogleTest's rule).
std::string PropertyCaseName(const ::testing::TestParamInfo<PropertyCase>& info) {
  std::string name = info.param.relative;
  name = name.substr(0, name.size() - std::string(".poly").size());
  char tau[32];
  std::snprintf(tau, sizeof(tau), "%g", info.param.tau_rel);
  name += "_" + ToString(info.param.measure) + "_tau" + tau;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

class Decompose2dPropertyTest : public ::testing::TestWithParam<PropertyCase> {};

TEST_P(Decompose2dPropertyTest, SucceedsAndPassesCheckDecomposition) {
  const PropertyCase& c = GetParam();
  std::vector<double> radii;
  const std::vector<Polygon2d> polygons = ReadPolygons(c.path, &radii);
  ASSERT_FALSE(polygons.empty());
  // One tau for the whole file, relative to its largest polygon (as `acdplan decompose
  // --tau-rel` does), so a small island next to a large polygon is judged on the same scale.
  const double radius = *std::max_element(radii.begin(), radii.end());
  Decompose2dOptions options;
  options.measure = c.measure;
  options.tau = c.tau_rel * radius;
  SCOPED_TRACE(c.relative + " measure " + ToString(c.measure) + " tau_rel " +
               std::to_string(c.tau_rel) + " tau " + std::to_string(options.tau));

  Decomposition2d decomposition;
  try {
    decomposition = Decompose2d(polygons, options);
  } catch (const std::exception& error) {
    FAIL() << "Decompose2d threw: " << error.what();
  }
  ASSERT_FALSE(decomposition.components.empty());
  EXPECT_EQ(decomposition.stats.components, static_cast<int>(decomposition.components.size()));
  EXPECT_EQ(decomposition.roots.size(), polygons.size());
  if (c.tau_rel == 0.0) {
    EXPECT_EQ(decomposition.stats.max_concavity, 0.0);
  }

  const DecompositionCheck check = CheckDecomposition(polygons, decomposition);
  std::string problems;
  for (const std::string& line : check.problems) problems += "\n  " + line;
  EXPECT_TRUE(check.ok()) << check.problems.size() << " problem(s):" << problems;
}

INSTANTIATE_TEST_SUITE_P(Acd2dCorpus, Decompose2dPropertyTest, ::testing::ValuesIn(PropertyCases()),
                         PropertyCaseName);

TEST(Decompose2dCorpusTest, CorpusIsComplete) {
  // 54 files, bird.poly broken: 53 x 4 measures x 5 tau values = 1060 property cases; under
  // the sanitizers one tau value per file and measure.
  EXPECT_EQ(PolygonCorpusFiles().size(), 54u);
  EXPECT_EQ(PropertyCases().size(), ACDPLAN_ASAN_BUILD ? 212u : 1060u);
}

std::string CorpusErrorOf(const std::string& path) {
  return acdplan::test::InputErrorOf([&] { ReadPolygons(path); });
}

TEST(Decompose2dCorpusTest, BirdIsRejectedAtLine47) {
  // Line 47 holds "-6.64248.788605": two numbers run together.
  EXPECT_THAT(CorpusErrorOf((kAcd2d / "bird.poly").string()),
              HasSubstr("bird.poly:47: malformed number '-6.64248.788605'"));
}

// --- Behaviour of Decompose2d() on small inline fixtures and the tree it returns. ---

std::string Problems(const DecompositionCheck& check) {
  std::string all;
  for (const std::string& line : check.problems) all += "\n  " + line;
  return all;
}

Polygon2d Prepared(const Polygon2d& raw) { return PreparePolygon(raw, "fixture"); }

// A comb: five teeth, four notches.
Polygon2d Comb() {
  return Prepared({{{0, 0}, {9, 0}, {9, 3}, {8, 3}, {8, 1}, {7, 1}, {7, 3}, {6, 3}, {6, 1}, {5, 1},
                    {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}},
                   {}});
}

Polygon2d LShape() { return Prepared({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}}); }

Polygon2d SquareWithHole() {
  return Prepared({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}});
}

std::string OptionsError(const Decompose2dOptions& options) {
  try {
    Decompose2d(LShape(), options);
  } catch (const acdplan::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Decompose2dTest, DefaultOptionsGiveConvexPieces) {
  const Polygon2d comb = Comb();
  const Decomposition2d d = Decompose2d(comb);
  EXPECT_EQ(d.tau, 0.0);
  EXPECT_EQ(d.measure, ConcavityMeasure::kShortestPath);
  EXPECT_GE(d.components.size(), 5u);  // At least one piece per tooth.
  for (const Component2d& c : d.components) {
    EXPECT_EQ(CountNotches(c.polygon), 0);
    EXPECT_EQ(c.concavity, 0.0);
    EXPECT_TRUE(c.polygon.holes.empty());
  }
  EXPECT_EQ(d.stats.notches, 8);  // Two per gap between teeth.
  EXPECT_EQ(d.stats.max_concavity, 0.0);
  const DecompositionCheck check = CheckDecomposition({comb}, d);
  EXPECT_TRUE(check.ok()) << Problems(check);
}

TEST(Decompose2dTest, LShapeAtTauZeroGivesTwoPiecesAndOneOpening) {
  const Decomposition2d d = Decompose2d(LShape());
  ASSERT_EQ(d.components.size(), 2u);
  ASSERT_EQ(d.openings.size(), 1u);
  const Opening2d& opening = d.openings[0];
  EXPECT_EQ(opening.component_a, 0);
  EXPECT_EQ(opening.component_b, 1);
  // The opening runs from the notch (1, 1) across the piece.
  EXPECT_TRUE(opening.a.isApprox(Point2d(1, 1)) || opening.b.isApprox(Point2d(1, 1)))
      << opening.a.transpose() << " - " << opening.b.transpose();
  EXPECT_NEAR(Area(d.components[0].polygon) + Area(d.components[1].polygon), 3.0, 1e-12);
  EXPECT_TRUE(CheckDecomposition({LShape()}, d).ok());
}

// Separate input polygons that meet along their boundaries (the pieces PreparePolygons() cuts a
// pinched polygon into, tiles of a map) open into each other there: the openings hold the
// shared segment, whole or in part, and only that.
TEST(Decompose2dTest, PolygonsMeetingAlongAnEdgeShareAnOpening) {
  const Polygon2d left = Prepared({{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {}});
  // Above `left`, offset by 1: the two share the segment (1, 1) - (2, 1).
  const Polygon2d above = Prepared({{{1, 1}, {3, 1}, {3, 2}, {1, 2}}, {}});
  const Decomposition2d d = Decompose2d(std::vector<Polygon2d>{left, above});
  ASSERT_EQ(d.components.size(), 2u);
  ASSERT_EQ(d.openings.size(), 1u);
  const Opening2d& opening = d.openings[0];
  EXPECT_EQ(opening.component_a, 0);
  EXPECT_EQ(opening.component_b, 1);
  const std::pair<Point2d, Point2d> ends = opening.a.x() < opening.b.x()
                                               ? std::make_pair(opening.a, opening.b)
                                               : std::make_pair(opening.b, opening.a);
  EXPECT_EQ(ends.first, Point2d(1, 1));
  EXPECT_EQ(ends.second, Point2d(2, 1));
  EXPECT_TRUE(CheckDecomposition({left, above}, d).ok());
  // A slanted shared edge (the seams of such edges are found by a box sweep).
  const Polygon2d below = Prepared({{{0, 0}, {2, 0}, {0, 2}}, {}});
  const Polygon2d beyond = Prepared({{{2, 0}, {2, 2}, {0, 2}}, {}});
  const Decomposition2d halves = Decompose2d(std::vector<Polygon2d>{below, beyond});
  ASSERT_EQ(halves.openings.size(), 1u);
  EXPECT_NEAR((halves.openings[0].a - halves.openings[0].b).norm(), std::sqrt(8.0), 1e-12);
  // Meeting at a point only, or apart: no opening.
  const Polygon2d corner = Prepared({{{2, 1}, {3, 1}, {3, 2}, {2, 2}}, {}});
  EXPECT_TRUE(Decompose2d(std::vector<Polygon2d>{left, corner}).openings.empty());
  const Polygon2d apart = Prepared({{{0, 1.5}, {2, 1.5}, {2, 2}, {0, 2}}, {}});
  EXPECT_TRUE(Decompose2d(std::vector<Polygon2d>{left, apart}).openings.empty());
  // A polygon whose cut pieces meet along a shared edge: L-shape pieces, each decomposed.
  const Polygon2d l_lower = Prepared({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}}, {}});
  const Polygon2d l_upper = Prepared({{{0, 1}, {1, 1}, {1, 2}, {0, 2}}, {}});
  const Decomposition2d l = Decompose2d(std::vector<Polygon2d>{l_lower, l_upper});
  ASSERT_EQ(l.openings.size(), 1u);
  EXPECT_EQ(l.components[static_cast<size_t>(l.openings[0].component_a)].source, 0);
  EXPECT_EQ(l.components[static_cast<size_t>(l.openings[0].component_b)].source, 1);
}

TEST(Decompose2dTest, SquareIsOneComponent) {
  const Polygon2d square = Prepared({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}});
  const Decomposition2d d = Decompose2d(square);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_EQ(d.components[0].concavity, 0.0);
  EXPECT_TRUE(d.openings.empty());
  EXPECT_EQ(d.tree.size(), 1u);
  EXPECT_EQ(d.stats.convexity, 1.0);
  EXPECT_TRUE(d.components[0].centroid.isApprox(Point2d(0.5, 0.5)));
}

TEST(Decompose2dTest, HoleAtTauZeroIsResolvedIntoConvexPieces) {
  const Polygon2d polygon = SquareWithHole();
  const Decomposition2d d = Decompose2d(polygon);
  EXPECT_GE(d.components.size(), 2u);  // A ring cannot be one convex piece.
  for (const Component2d& c : d.components) {
    EXPECT_TRUE(c.polygon.holes.empty());
    EXPECT_EQ(CountNotches(c.polygon), 0);
  }
  // The first split cuts the hole open with two cuts (p and cw(p), Eqn. 4.2).
  ASSERT_FALSE(d.tree.empty());
  EXPECT_EQ(d.tree[d.roots[0]].cuts.size(), 2u);
  const DecompositionCheck check = CheckDecomposition({polygon}, d);
  EXPECT_TRUE(check.ok()) << Problems(check);
}

TEST(Decompose2dTest, LargeTauKeepsTheHoleInOneComponent) {
  const Polygon2d polygon = SquareWithHole();
  Decompose2dOptions options;
  options.tau = 1e3;  // Far above any concavity of a 4 x 4 square.
  const Decomposition2d d = Decompose2d(polygon, options);
  ASSERT_EQ(d.components.size(), 1u);
  ASSERT_EQ(d.components[0].polygon.holes.size(), 1u);
  EXPECT_GT(d.components[0].concavity, 0.0);  // A hole has positive concavity (Eqn. 4.2).
  EXPECT_LE(d.components[0].concavity, options.tau);
  EXPECT_NEAR(Area(d.components[0].polygon), 12.0, 1e-12);
  EXPECT_TRUE(d.openings.empty());
  const DecompositionCheck check = CheckDecomposition({polygon}, d);
  EXPECT_TRUE(check.ok()) << Problems(check);
}

// Two long holes side by side, 1 apart, 2 from the outer boundary: a wall between two cells.
Polygon2d TwoCells() {
  return Prepared({{{0, 0}, {21, 0}, {21, 6}, {0, 6}},
                   {{{2, 2}, {2, 4}, {10, 4}, {10, 2}}, {{11, 2}, {11, 4}, {19, 4}, {19, 2}}}});
}

TEST(Decompose2dTest, HolesCloserToEachOtherThanToTheBoundaryAreCutInOneSplit) {
  // Each hole links to its closest ring (Eqn. 4.2), here the other hole: the first split runs
  // from the outer boundary through both holes back to it (three cuts), so two pieces remain,
  // each within tau; cutting the holes one at a time (two cuts each) leaves three (below).
  const Polygon2d polygon = TwoCells();
  for (const ConcavityMeasure measure :
       {ConcavityMeasure::kStraightLine, ConcavityMeasure::kHybrid2,
        ConcavityMeasure::kShortestPath}) {
    Decompose2dOptions options;
    options.measure = measure;
    options.tau = 4.0;  // Below either hole's concavity (> its diameter, 8.2), above a pocket's.
    const Decomposition2d d = Decompose2d(polygon, options);
    const HierarchyNode2d& root = d.tree[d.roots[0]];
    EXPECT_EQ(root.cuts.size(), 3u) << ToString(measure);
    EXPECT_EQ(d.components.size(), 2u) << ToString(measure);
    for (const Component2d& c : d.components) EXPECT_TRUE(c.polygon.holes.empty());
    const DecompositionCheck check = CheckDecomposition({polygon}, d);
    EXPECT_TRUE(check.ok()) << ToString(measure) << Problems(check);
  }
}

TEST(Decompose2dTest, HolesCloserToTheBoundaryAreCutOneAtATime) {
  // The same holes 5 apart: each is closer to the outer boundary than to the other, so each is
  // linked to it (two cuts per split, as Fig. 19), never through the other hole.
  const Polygon2d polygon =
      Prepared({{{0, 0}, {25, 0}, {25, 6}, {0, 6}},
                {{{2, 2}, {2, 4}, {10, 4}, {10, 2}}, {{15, 2}, {15, 4}, {23, 4}, {23, 2}}}});
  Decompose2dOptions options;
  options.measure = ConcavityMeasure::kStraightLine;
  options.tau = 4.0;
  const Decomposition2d d = Decompose2d(polygon, options);
  for (const HierarchyNode2d& node : d.tree) {
    if (node.children[0] >= 0) {
      EXPECT_LE(node.cuts.size(), 2u);
    }
  }
  EXPECT_EQ(d.components.size(), 3u);
  const DecompositionCheck check = CheckDecomposition({polygon}, d);
  EXPECT_TRUE(check.ok()) << Problems(check);
}

TEST(Decompose2dTest, NeuronAtTauRelOnePercentHasAtMost160Components) {
  // The count of Lien's reference implementation on this polygon at tau_rel 0.01.
  std::vector<double> radii;
  const std::vector<Polygon2d> neuron =
      ReadPolygons((kAcd2d / "neuron" / "neuron.poly").string(), &radii);
  for (const ConcavityMeasure measure :
       {ConcavityMeasure::kStraightLine, ConcavityMeasure::kHybrid2}) {
    Decompose2dOptions options;
    options.measure = measure;
    options.tau = 0.01 * *std::max_element(radii.begin(), radii.end());
    const Decomposition2d d = Decompose2d(neuron, options);
    EXPECT_LE(d.components.size(), 160u) << ToString(measure);
    const DecompositionCheck check = CheckDecomposition(neuron, d);
    EXPECT_TRUE(check.ok()) << ToString(measure) << Problems(check);
  }
}

TEST(Decompose2dTest, MinConvexityBoundsEveryComponentsAreaRatio) {
  const std::vector<Polygon2d> monkey =
      ReadPolygons((kAcd2d / "nazca" / "nazca_monkey.poly").string());
  Decompose2dOptions options;
  options.min_convexity = 0.9;  // Algorithm 9 (shape decomposition).
  const Decomposition2d d = Decompose2d(monkey, options);
  EXPECT_EQ(d.min_convexity, 0.9);
  ASSERT_GT(d.components.size(), 1u);
  for (size_t k = 0; k < d.components.size(); ++k) {
    const Component2d& c = d.components[k];
    EXPECT_GE(Area(c.polygon) / std::abs(SignedArea(c.hull)), 0.9 * (1.0 - 1e-12))
        << "component " << k;
  }
  EXPECT_GE(d.stats.convexity, 0.9);
  const DecompositionCheck check = CheckDecomposition(monkey, d);
  EXPECT_TRUE(check.ok()) << Problems(check);
  // Coarser than the exact convex decomposition.
  EXPECT_LT(d.components.size(), Decompose2d(monkey).components.size());
}

TEST(Decompose2dTest, InvalidOptionsThrowInputErrorNamingTheRule) {
  Decompose2dOptions negative_tau;
  negative_tau.tau = -1.0;
  EXPECT_THAT(OptionsError(negative_tau),
              HasSubstr("Decompose2d(): tau must be a finite number >= 0, got -1"));
  Decompose2dOptions nan_tau;
  nan_tau.tau = std::nan("");
  EXPECT_THAT(OptionsError(nan_tau), HasSubstr("Decompose2d(): tau must be a finite number"));
  Decompose2dOptions convexity;
  convexity.min_convexity = 1.5;
  EXPECT_THAT(OptionsError(convexity),
              HasSubstr("Decompose2d(): min_convexity must be in [0, 1], got 1.5"));
  Decompose2dOptions distance;
  distance.score_distance = 0.0;
  EXPECT_THAT(OptionsError(distance), HasSubstr("Decompose2d(): score_distance must be > 0"));
  Decompose2dOptions concavity;
  concavity.score_concavity = -0.1;
  EXPECT_THAT(OptionsError(concavity), HasSubstr("Decompose2d(): score_concavity must be >= 0"));
}

// The hierarchy of Ch. III (Fig. 9(b)): one root per input polygon, consistent links, every
// leaf a component and every component a leaf, internal nodes split by one cut (a notch) or
// two (a hole).
void ExpectConsistentTree(const std::vector<Polygon2d>& input, const Decomposition2d& d) {
  ASSERT_EQ(d.roots.size(), input.size());
  const int nodes = static_cast<int>(d.tree.size());
  std::vector<int> leaf_of(d.components.size(), -1);
  for (size_t r = 0; r < d.roots.size(); ++r) {
    ASSERT_GE(d.roots[r], 0);
    ASSERT_LT(d.roots[r], nodes);
    EXPECT_EQ(d.tree[d.roots[r]].parent, -1);
    EXPECT_EQ(d.tree[d.roots[r]].depth, 0);
    EXPECT_NEAR(Area(d.tree[d.roots[r]].piece), Area(input[r]), 1e-12 * Area(input[r]));
  }
  int roots_seen = 0;
  for (int n = 0; n < nodes; ++n) {
    const HierarchyNode2d& node = d.tree[n];
    if (node.parent < 0) {
      ++roots_seen;
    } else {
      ASSERT_LT(node.parent, nodes);
      const HierarchyNode2d& parent = d.tree[node.parent];
      EXPECT_TRUE(parent.children[0] == n || parent.children[1] == n) << "node " << n;
      EXPECT_EQ(node.depth, parent.depth + 1) << "node " << n;
    }
    const bool leaf = node.children[0] < 0;
    EXPECT_EQ(leaf, node.children[1] < 0) << "node " << n << " has one child";
    if (leaf) {
      ASSERT_GE(node.component, 0) << "leaf " << n;
      ASSERT_LT(node.component, static_cast<int>(d.components.size())) << "leaf " << n;
      EXPECT_EQ(leaf_of[node.component], -1) << "component " << node.component << " twice";
      leaf_of[node.component] = n;
      EXPECT_TRUE(node.cuts.empty());
      EXPECT_EQ(VertexCount(node.piece), VertexCount(d.components[node.component].polygon));
    } else {
      EXPECT_EQ(node.component, -1) << "internal node " << n;
      for (int child : node.children) {
        ASSERT_LT(child, nodes);
        EXPECT_EQ(d.tree[child].parent, n);
      }
      // One cut at a notch; or k + 1 cuts along a path through the k holes it resolves.
      ASSERT_GE(node.cuts.size(), 1u) << "internal node " << n;
      const size_t resolved = node.piece.holes.size() -
                              d.tree[node.children[0]].piece.holes.size() -
                              d.tree[node.children[1]].piece.holes.size();
      EXPECT_EQ(node.cuts.size(), resolved + 1)
          << "internal node " << n << " has " << node.cuts.size() << " cuts";
      // The children tile their parent.
      const double area = Area(node.piece);
      EXPECT_NEAR(Area(d.tree[node.children[0]].piece) + Area(d.tree[node.children[1]].piece), area,
                  1e-9 * area)
          << "node " << n;
    }
  }
  EXPECT_EQ(roots_seen, static_cast<int>(d.roots.size()));
  for (size_t k = 0; k < leaf_of.size(); ++k) {
    EXPECT_NE(leaf_of[k], -1) << "component " << k << " is no leaf";
    EXPECT_GE(d.components[k].source, 0);
    EXPECT_LT(d.components[k].source, static_cast<int>(input.size()));
  }
}

TEST(Decompose2dTest, TreeIsConsistent) {
  Decompose2dOptions keep;
  keep.keep_pieces = true;
  const std::vector<Polygon2d> monkey =
      ReadPolygons((kAcd2d / "nazca" / "nazca_monkey.poly").string());
  ExpectConsistentTree(monkey, Decompose2d(monkey, keep));
  const std::vector<Polygon2d> neuron = ReadPolygons((kAcd2d / "neuron" / "neuron.poly").string());
  Decompose2dOptions sl = keep;
  sl.measure = ConcavityMeasure::kStraightLine;
  ExpectConsistentTree(neuron, Decompose2d(neuron, sl));
  // 234 polygons in one call: one root each, components keep their source.
  const std::vector<Polygon2d> nacd = ReadPolygons((kAcd2d / "neuron" / "nacd.poly").string());
  ExpectConsistentTree(nacd, Decompose2d(nacd, keep));
  ExpectConsistentTree({LShape()}, Decompose2d(LShape(), keep));
}

TEST(Decompose2dTest, WithoutKeepPiecesOnlyRootsKeepTheirPieces) {
  const std::vector<Polygon2d> neuron = ReadPolygons((kAcd2d / "neuron" / "neuron.poly").string());
  for (const ConcavityMeasure measure :
       {ConcavityMeasure::kStraightLine, ConcavityMeasure::kShortestPath}) {
    Decompose2dOptions options;
    options.measure = measure;
    options.tau = 0.01 * ReferenceRadius(neuron.front());
    const Decomposition2d light = Decompose2d(neuron, options);
    options.keep_pieces = true;
    const Decomposition2d kept = Decompose2d(neuron, options);
    // The same decomposition; the tree without the pieces below its roots.
    ASSERT_EQ(light.components.size(), kept.components.size());
    for (size_t k = 0; k < kept.components.size(); ++k) {
      EXPECT_EQ(light.components[k].polygon.outer, kept.components[k].polygon.outer);
      EXPECT_EQ(light.components[k].hull, kept.components[k].hull);
    }
    ASSERT_EQ(light.tree.size(), kept.tree.size());
    ASSERT_GT(light.tree.size(), 100u);
    for (size_t n = 0; n < light.tree.size(); ++n) {
      const bool root = light.tree[n].parent < 0;
      EXPECT_EQ(light.tree[n].piece.outer.empty(), !root) << "node " << n;
      EXPECT_EQ(light.tree[n].cuts.size(), kept.tree[n].cuts.size()) << "node " << n;
      EXPECT_FALSE(kept.tree[n].piece.outer.empty()) << "node " << n;
    }
    EXPECT_EQ(light.openings.size(), kept.openings.size());
  }
}

// Reproduction, found on star6.poly (SL/SP/H1/H2, tau 0) at commit 06938f8: the quadrilateral
// a b c d below (exactly simple; c is a notch) split by its diagonal c-a into the triangles
// c d a and a b c. The second is a needle of area 5e-17 (c lies 1.6e-15 from the line ab), and
// the two are interior-disjoint in exact arithmetic, yet CheckDecomposition() (then) reported
// "components 0 and 1 overlap near (16.00195, -17.0039)".
TEST(Decompose2dRepro, CheckDecompositionAcceptsNeedleNextToItsNeighbour) {
  const Point2d a(15.9922, -16.984400000000001), b(16.0215, -17.042999999999999),
      c(16.011700000000001, -17.023399999999999), d(16.001999999999999, -17.003900000000002);
  const Polygon2d input{{a, b, c, d}, {}};
  Decomposition2d decomposition;
  for (const Ring2d& ring : {Ring2d{c, d, a}, Ring2d{a, b, c}}) {
    Component2d component;
    component.polygon.outer = ring;
    component.hull = ConvexHull(ring);
    component.centroid = Centroid(component.polygon);
    component.concavity = 0.0;
    decomposition.components.push_back(component);
  }
  decomposition.openings.push_back({c, a, 0, 1});
  decomposition.roots = {0};
  decomposition.stats.components = 2;
  double area = 0.0, hull_area = 0.0;
  for (const Component2d& component : decomposition.components) {
    area += Area(component.polygon);
    hull_area += SignedArea(component.hull);
  }
  decomposition.stats.convexity = area / hull_area;
  const DecompositionCheck check = CheckDecomposition({input}, decomposition);
  EXPECT_TRUE(check.ok()) << Problems(check);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-far-vertex-grid-cell.poly):
// vertices 10^7 and 5.3 * 10^7 away from the others put a point so far outside the triangulation
// grid of the reflex vertices that its cell offset overflowed int (undefined behaviour, which
// the sanitizer suite reports). Every measure must now decompose it validly.
TEST(Decompose2dTest, VerticesFarOutsideTheReflexVerticesBox) {
  std::istringstream in(
      "1\n8 out\n0.000000 -13.000000\n10000000. -7.200000\n8.000000 3.000000\n"
      "3.000015 9.000000\n-53000000 6.000000\n-3.000000 2.000000\n-8.000000 0.000000\n"
      "-7.000000 -10.000000\n1 2 3 4 5 6 7 8\n");
  const std::vector<Polygon2d> raw = ReadPoly(in, "far.poly");
  ASSERT_EQ(raw.size(), 1u);
  const std::vector<Polygon2d> input = PreparePolygons(raw[0], "far.poly");
  ASSERT_EQ(input.size(), 1u);
  for (const ConcavityMeasure measure : kMeasures) {
    for (const double tau : {0.0, 0.05 * ReferenceRadius(input[0])}) {
      Decompose2dOptions options;
      options.tau = tau;
      options.measure = measure;
      const DecompositionCheck check = CheckDecomposition(input, Decompose2d(input, options));
      EXPECT_TRUE(check.ok()) << ToString(measure) << ", tau " << tau << ": "
                              << ::testing::PrintToString(check.problems);
    }
  }
}

// The polygons of fuzz/corpus/decompose2d/`file`, a regression input kept by the fuzzer.
std::vector<Polygon2d> FuzzRegressionInput(const std::string& file) {
  return ReadPolygons(
      (fs::path(acdplan::test::SourceDir()) / "fuzz" / "corpus" / "decompose2d" / file).string());
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-huge-spike-area.poly and
// regression-zero-area-component.wkt): coordinates of 5.56e21 and 5e58 make the shoelace terms
// cancel far beyond double precision. The decompositions were right (the exact area sums agree:
// 2191.5 for the spike, 5e58 + 5 for the wedge); the double-precision SignedArea() was not, so
// CheckDecomposition() saw an input area of 2075.5 and a component of zero area. Every measure
// must now decompose both validly, with the exact input area. Coordinates above 1e100 are
// rejected by PreparePolygons() (regression-overflowing-coordinate.wkt).
TEST(Decompose2dTest, HugeCoordinatesWhoseAreaTermsCancel) {
  // The last: the wedge at the largest magnitude PreparePolygons() accepts (1e100).
  const std::pair<std::string, double> cases[] = {{"regression-huge-spike-area.poly", 2191.5},
                                                  {"regression-zero-area-component.wkt", 5e58},
                                                  {"", 1e100 + 98.5}};
  for (const auto& [file, area] : cases) {
    const std::vector<Polygon2d> input =
        !file.empty() ? FuzzRegressionInput(file)
                      : PreparePolygons({{{0, 0}, {1, 4}, {1, 2}, {1e100, 199}, {0, 4}}, {}}, "w");
    ASSERT_EQ(input.size(), 1u) << file;
    EXPECT_EQ(Area(input[0]), area) << file;
    for (const ConcavityMeasure measure : kMeasures) {
      for (const double tau : {0.0, 0.05 * ReferenceRadius(input[0])}) {
        Decompose2dOptions options;
        options.tau = tau;
        options.measure = measure;
        const Decomposition2d decomposition = Decompose2d(input, options);
        const DecompositionCheck check = CheckDecomposition(input, decomposition);
        EXPECT_TRUE(check.ok()) << file << ", " << ToString(measure) << ", tau " << tau << ": "
                                << ::testing::PrintToString(check.problems);
        for (const Component2d& c : decomposition.components) {
          EXPECT_GT(SignedArea(c.polygon.outer), 0.0) << file;
        }
      }
    }
  }
}

// Each of `inputs` (one prepared polygon each) decomposes under every measure, at tau = 0 and at
// tau_rel x its reference radius, and passes CheckDecomposition(); at tau = 0 into at least two
// components when `each_has_a_notch`.
void ExpectEveryMeasureDecomposes(const std::vector<std::vector<Polygon2d>>& inputs, double tau_rel,
                                  bool each_has_a_notch = true) {
  for (size_t k = 0; k < inputs.size(); ++k) {
    const std::vector<Polygon2d>& input = inputs[k];
    ASSERT_EQ(input.size(), 1u) << "input " << k;
    for (const ConcavityMeasure measure : kMeasures) {
      for (const double tau : {0.0, tau_rel * ReferenceRadius(input[0])}) {
        const std::string label = "input " + std::to_string(k) + ", " + ToString(measure) +
                                  ", tau " + std::to_string(tau);
        Decompose2dOptions options;
        options.tau = tau;
        options.measure = measure;
        Decomposition2d decomposition;
        ASSERT_NO_THROW(decomposition = Decompose2d(input, options)) << label;
        const DecompositionCheck check = CheckDecomposition(input, decomposition);
        EXPECT_TRUE(check.ok()) << label << ": " << ::testing::PrintToString(check.problems);
        if (tau == 0.0 && each_has_a_notch) {
          EXPECT_GE(decomposition.components.size(), 2u) << label;
        }
      }
    }
  }
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-thin-polygon-cut-end-near-
// edge.wkt, a ring that touches itself, repaired into two polygons): the first is a needle
// 3.5e-6 wide and 1 long near (14.9, 16.5). At tau = 0 one cut ends at a point constructed on
// another cut, 7e-12 from the end of an input edge: within that edge's rounding noise, so
// CheckDecomposition() took it for a point splitting the edge and added the triangle it makes
// with the edge, 3.8e-13, to the input's area. The components tiled the needle (their areas
// summed to it within 4e-16), but the check failed for every measure, and `acdplan decompose
// --repair` refused the file with an internal error. A point counts as splitting an edge only if
// the union's boundary runs along that edge from it. Then (regression-thin-polygon-t-junction-
// area.wkt) a piece of area 5.5e-15 whose cut ends on another cut, rounded off it: a triangle of
// 5.7e-24, 1.05e-9 of the area, beyond the check's relative tolerance; the check now allows each
// constructed point its rounding (half its noise times the edges at it).
TEST(Decompose2dTest, ThinPolygonWhoseCutEndLiesWithinNoiseOfAnEdge) {
  ReadPolygonsOptions repair;
  repair.repair = true;
  std::vector<std::vector<Polygon2d>> inputs;
  for (const char* file : {"regression-thin-polygon-cut-end-near-edge.wkt",
                           "regression-thin-polygon-t-junction-area.wkt"}) {
    for (const Polygon2d& polygon : ReadPolygons(
             (fs::path(acdplan::test::SourceDir()) / "fuzz" / "corpus" / "decompose2d" / file)
                 .string(),
             nullptr, repair)) {
      inputs.push_back({polygon});
    }
  }
  ASSERT_EQ(inputs.size(), 8u);
  // The needle alone, as the repair gives it.
  inputs.push_back(PreparePolygons({{{14.913040000000001, 16},
                                     {14.913043478260867, 16.000039998400052},
                                     {14.91304347826086, 16.5},
                                     {14.913043468260868, 16.608001000520002},
                                     {14.913043468277587, 16.608002113691995},
                                     {14.913043468260868, 16.608001371371568},
                                     {14.91304347869565, 16.608695699130433},
                                     {14.913043483913041, 16.608696262599999},
                                     {14.913043478260869, 17}},
                                    {}},
                                   "needle"));
  // Some of the repair's pieces are convex: one component at tau = 0.
  ExpectEveryMeasureDecomposes(inputs, 0.05, /*each_has_a_notch=*/false);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-long-edge-bisector-snap.wkt):
// in (0 0, 1 4, 1 2, 64526540 10, 0 4) no vertex lies in the cone of the notch (1, 4), so only
// its bisector's hit resolves it; that hit lies 1e-7 from the notch on the 6.5e7-long edge, at
// edge parameter 1 - 1.5e-8, and was snapped to the edge's end (0, 4), 1 unit away and outside
// the cone ("could not resolve a piece"). The hit now snaps only within rounding noise, and is
// constructed from the nearer edge end. The same wedge at other lengths and mirrored, too.
TEST(Decompose2dTest, BisectorHitNearTheEndOfAVeryLongEdge) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-long-edge-bisector-snap.wkt")};
  for (const double far : {1e3, 1e6, 64526540.0, 1e9, 1e12}) {
    inputs.push_back(PreparePolygons({{{0, 0}, {1, 4}, {1, 2}, {far, 10}, {0, 4}}, {}}, "w"));
    inputs.push_back(PreparePolygons({{{0, 0}, {0, 4}, {-far, 10}, {-1, 2}, {-1, 4}}, {}}, "m"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.01);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-huge-edge-clear-cut.wkt, its
// third coordinate ignored): in (0 0, 4 0, 2 6, 4 4.1e26, 0 2, 2 2) the notch (2, 2) is resolved
// only by its bisector's hit on the edge (4 0)-(2 6), a constructed point, which must keep clear
// of the other vertices and edges by its rounding noise. That was tested on floating-point
// distances with a margin for their rounding, which grows with the edges' coordinates: 4e13
// next to the edges to (4, 4.1e26), so every cut among the small features was refused ("could
// not resolve a piece"). The nearness is now decided exactly. The same shape at other heights
// and mirrored, too.
TEST(Decompose2dTest, CutAmongTheSmallFeaturesOfAPolygonWithAHugeEdge) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-huge-edge-clear-cut.wkt")};
  for (const double far : {1e6, 1e14, 1e40, 1e99}) {
    inputs.push_back(
        PreparePolygons({{{0, 0}, {4, 0}, {2, 6}, {4, far}, {0, 2}, {2, 2}}, {}}, "spike"));
    inputs.push_back(
        PreparePolygons({{{-2, 2}, {0, 2}, {-4, far}, {-2, 6}, {-4, 0}, {0, 0}}, {}}, "mirrored"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.01);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-long-edge-area-sliver.wkt,
// the wedge (0 0, 1 4, 1557048468 199, 0 4)): the notch (1, 4) lies 1.25e-7 below the long top
// edge, and its cut ends on that edge at a constructed point, rounded off the edge by about an
// ulp of its coordinates (~1e-16), which moves the boundary by that times the edge's length:
// the components' areas summed to 99.5 + 1.9e-7 against the input's 99.5, beyond the relative
// tolerance of CheckDecomposition(), which now compares with the input's area plus each edge's
// sliver through the points constructed on it. The same wedge at other lengths, too.
TEST(Decompose2dTest, ComponentsCutOnAVeryLongEdgeTileTheInput) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-long-edge-area-sliver.wkt")};
  for (const double far : {1e4, 1557048468.0, 1e12}) {
    inputs.push_back(PreparePolygons({{{0, 0}, {1, 4}, {far, 199}, {0, 4}}, {}}, "wedge"));
  }
  // Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-long-edge-wide-noise.wkt,
  // repaired into this wedge) while the test of PointsNearANeedleEdgeAddNoSliver for a point a
  // component's edge runs through allowed that edge's noise, which along an edge 5e12 long took in
  // the cut end beside it: its sliver was dropped.
  inputs.push_back(PreparePolygons({{{0, 0}, {1, 4}, {5175040148996, 9}, {0, 4}}, {}}, "wedge"));
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Found by fuzz/fuzz_decompose2d (polygons made valid by RepairPolygon(), kept as
// fuzz/corpus/decompose2d/regression-needle-cut-point-sliver.wkt and, found by CI's fuzz run from
// that seed, regression-needle-diagonal-t-junction.wkt): the edge from (17, 18 - 4e-15) up to
// (18, 5.6e21) passes 3.6e-22 from the point (17, 20), where a cut meets the diagonal x = 17 that
// closes off the needle. The exact areas of the components sum to the input's, but
// CheckDecomposition() took (17, 20) for a point the edge is split at and added the sliver of the
// chain through it, an area of 1 (half the edge's length times 3.6e-22). The needle's component
// keeps the edge whole and its diagonal runs straight through (17, 20): a point some component's
// edge runs through now splits no input edge. The same shape with other spikes, too.
TEST(Decompose2dTest, PointsNearANeedleEdgeAddNoSliver) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-needle-cut-point-sliver.wkt"),
      FuzzRegressionInput("regression-needle-diagonal-t-junction.wkt")};
  for (const double far : {1e15, 1e30}) {
    inputs.push_back(PreparePolygons({{{14, 19},
                                       {16, 19},
                                       {16, 18},
                                       {15, 17},
                                       {14.913043478260869, 16.60869565217391},
                                       {17, 18},
                                       {17, 17.999999999999996},
                                       {18, far},
                                       {17, 22},
                                       {17, 21},
                                       {16, 2051},
                                       {15, 20}},
                                      {}},
                                     "spike"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-needle-foot-cut-sliver.wkt,
// one of six polygons RepairPolygon() made of a ring crossing itself): a needle up to y = 5516,
// its sides 1e-14 apart at its foot, is cut off by a diagonal from its foot; a second cut ends on
// that diagonal at a point 1e-12 off the needle's edge, within that edge's noise, and the
// diagonal's end is on the edge too. The exact areas of the components sum to the input's, but
// CheckDecomposition() credited the sliver from that point to the needle's edge, 2.9e-9 (of an
// area of 1e-3), and failed the tiling. The same needle 10 to 10,000 times as long.
TEST(Decompose2dTest, CutFromTheFootOfANeedleAddsNoSliver) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-needle-foot-cut-sliver.wkt")};
  const Ring2d found = inputs[0][0].outer;
  ASSERT_EQ(found.size(), 9u);
  ASSERT_GT(std::min(found[7].y(), found[8].y()), 5000.0);   // The needle's tip, as in the file.
  for (const double stretch : {10.0, 100.0, 1000.0, 1e4}) {  // The needle's sides from its foot.
    Ring2d ring = found;
    ring[7] = ring[6] + stretch * (found[7] - found[6]);
    ring[8] = ring[0] + stretch * (found[8] - found[0]);
    inputs.push_back(PreparePolygons({ring, {}}, "needle"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-underflowing-cut-length.wkt):
// in (1 0, 9 90, 1 2, 1 1e-194, 0 0) the only cut that resolves the notch (1, 1e-194) goes to
// the vertex (1, 0) straight below it, 1e-194 away, whose squared length underflows to 0: the
// cut's score took its length as 0, as for the notch itself, and refused it ("could not resolve
// a piece"). The same wedge with other gaps, down to a subnormal one.
TEST(Decompose2dTest, CutShorterThanTheSquareRootOfTheSmallestDouble) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-underflowing-cut-length.wkt")};
  for (const double gap : {1e-20, 1e-160, 1e-300, 1e-310}) {
    inputs.push_back(PreparePolygons({{{1, 0}, {9, 90}, {1, 2}, {1, gap}, {0, 0}}, {}}, "wedge"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Found by fuzz/fuzz_decompose2d (a shapefile seed; fuzz/corpus/decompose2d/regression-subnormal-
// pocket.wkt): a pocket of vertices within 1e-310 of the corner (0, 0) has an area below what a
// double holds, and SP, H1 and H2 refused it ("the pocket polygon has zero area", an exception
// out of Decompose2d()): the pocket's side of its bridge was taken from the sign of its area.
// It is now the exact orientation of a pocket vertex against the bridge.
TEST(Decompose2dTest, PocketOfSubnormalCoordinates) {
  ExpectEveryMeasureDecomposes({FuzzRegressionInput("regression-subnormal-pocket.wkt")}, 0.05);
}

// Found by fuzz/fuzz_decompose2d (a shapefile; fuzz/corpus/decompose2d/regression-underflowing-
// sliver-area.wkt): above y = 0 the polygon is the triangle (0 0, 1e-307 0, 30 7.1e-307), whose
// area, 3.6e-614, no double holds. The decomposition cut it off as it should, and
// CheckDecomposition() called the component's outer ring and hull of zero area, from the
// doubles' sign; its centroid divided by that zero. The signs are now exact where the double
// area is 0, and such a component's centroid is its vertex mean.
TEST(Decompose2dTest, ComponentWhoseAreaUnderflows) {
  const std::vector<Polygon2d> input =
      FuzzRegressionInput("regression-underflowing-sliver-area.wkt");
  ExpectEveryMeasureDecomposes({input}, 0.05);
  Decompose2dOptions options;
  options.tau = 0.0;
  const Decomposition2d decomposition = Decompose2d(input, options);
  int slivers = 0;
  for (const Component2d& component : decomposition.components) {
    if (Area(component.polygon) != 0.0) continue;
    ++slivers;
    EXPECT_TRUE(component.centroid.allFinite());
    EXPECT_GT(component.centroid.x(), 0.0);  // Within the sliver's box.
    EXPECT_LT(component.centroid.x(), 30.0);
  }
  EXPECT_EQ(slivers, 1);
}

// Found by fuzz/fuzz_decompose2d (a polygon made valid by RepairPolygon(), minimised to
// fuzz/corpus/decompose2d/regression-vertex-near-split-edge.wkt): in (17 14, 18 5.6e22, 7 22,
// 16 2051, 17 21) the vertex (17, 21) lies 1.3e-22 left of the edge from (17, 14) up to the
// spike. A cut ended on that edge at (17, 2558.2), rounded onto x = 17 exactly; the piece's new
// edge (17, 14)-(17, 2558.2) then ran through (17, 21), a pinch no later cut resolves ("could
// not resolve a piece"). A cut may now end on an edge only where no other vertex lies within
// the end's rounding noise of it. The same shape with other spikes, and mirrored, too.
TEST(Decompose2dTest, CutEndsOnlyOnEdgesClearOfOtherVertices) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-vertex-near-split-edge.wkt")};
  for (const double far : {1e15, 5.5555555555555555e22, 1e40}) {
    inputs.push_back(
        PreparePolygons({{{17, 14}, {18, far}, {7, 22}, {16, 2051}, {17, 21}}, {}}, "spike"));
    inputs.push_back(PreparePolygons(
        {{{-17, 21}, {-16, 2051}, {-7, 22}, {-18, far}, {-17, 14}}, {}}, "mirrored"));
  }
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Two cut ends that score the same (the notch's bisector hit, closer, is no candidate without
// Steiner cuts): the earlier along the ring is taken, whichever vertex the ring starts at. The
// tie went to whatever the standard library's heap popped first, so dsb.poly and torus2.poly
// decomposed differently with libc++ than with libstdc++.
TEST(Decompose2dTest, TiedCutEndsGoToTheEarlierAlongTheRing) {
  const Ring2d ring = {{0, 0}, {4, 0}, {4, 3}, {2, 2.5}, {0, 3}};  // Notch (2, 2.5).
  Decompose2dOptions options;
  options.measure = ConcavityMeasure::kStraightLine;
  options.steiner_cuts = false;
  for (int start = 0; start < 5; ++start) {
    Ring2d rotated;
    for (int i = 0; i < 5; ++i) rotated.push_back(ring[(start + i) % 5]);
    const Decomposition2d d = Decompose2d(Polygon2d{rotated, {}}, options);
    ASSERT_EQ(d.tree[0].cuts.size(), 1u) << "start " << start;
    // (4, 0) comes before (0, 0) only in the ring that starts at it.
    const Point2d expected = start == 1 ? Point2d(4, 0) : Point2d(0, 0);
    EXPECT_EQ(d.tree[0].cuts[0].from, Point2d(2, 2.5)) << "start " << start;
    EXPECT_EQ(d.tree[0].cuts[0].to, expected) << "start " << start;
  }
}

// Found by fuzz/fuzz_decompose2d (a polygon made valid by RepairPolygon(), minimised to
// fuzz/corpus/decompose2d/regression-notch-within-noise-of-edge.wkt): the notch (999, 4) lies
// 7e-15 below the edge from (1.7e8, 4.0000000013) to (91, 4), and every cut that resolves it
// ends on that edge within 7e-15 of it, inside the band of rounding noise (1e-13 x the cut's
// largest coordinate) that a constructed cut end must keep clear of other edges: every cut was
// refused ("could not resolve a piece"). The last resort takes the first cut that crosses nothing
// and leaves two simple pieces, both checked exactly. The same shape with other gaps and lengths.
TEST(Decompose2dTest, NotchWithinRoundingNoiseOfAnEdge) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-notch-within-noise-of-edge.wkt")};
  for (const double far : {1e6, 1.6666666422434840e8, 1e12}) {
    for (const double rise : {1e-12, 1.3078187e-9}) {
      inputs.push_back(PreparePolygons(
          {{{91, 4}, {334, 2}, {999, 4}, {0.6 * far, 2}, {far, 4 + rise}}, {}}, "sliver"));
    }
  }
  ExpectEveryMeasureDecomposes(inputs, 0.05);
}

// Found by fuzz/fuzz_decompose2d (a polygon made valid by RepairPolygon(), minimised to
// fuzz/corpus/decompose2d/regression-near-collinear-cut-opening.wkt): at tau = 0 a cut A-B was
// followed by a cut A'-B from a point A' 1e-8 beside A, 1e-3 rad off the first. FindOpenings()
// took an edge for lying on a cut when both its ends were within 1e-9 of the coordinates'
// magnitude of its line, so the piece that touches A-B at B alone was paired across all of A-B
// (its end A not on that piece's boundary), and another pair of pieces was listed twice. The same
// shape mirrored; every opening's ends lie on both its pieces (CheckDecomposition()), and no
// opening is listed twice.
TEST(Decompose2dTest, OpeningsPairOnlyPiecesAlongTheCut) {
  std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-near-collinear-cut-opening.wkt")};
  Polygon2d mirrored = inputs[0][0];
  for (Point2d& p : mirrored.outer) p.x() = -p.x();
  std::reverse(mirrored.outer.begin(), mirrored.outer.end());
  inputs.push_back(PreparePolygons(mirrored, "mirrored"));
  ExpectEveryMeasureDecomposes(inputs, 0.05);
  for (const std::vector<Polygon2d>& input : inputs) {
    const Decomposition2d decomposition = Decompose2d(input, Decompose2dOptions{});
    const auto key = [](const Opening2d& o) {
      return std::make_tuple(o.component_a, o.component_b, o.a.x(), o.a.y(), o.b.x(), o.b.y());
    };
    std::set<decltype(key(Opening2d{}))> seen;
    for (const Opening2d& opening : decomposition.openings) {
      EXPECT_TRUE(seen.insert(key(opening)).second)
          << "opening between " << opening.component_a << " and " << opening.component_b
          << " listed twice";
    }
  }
}

// Slivers whose coordinates reach 5e58 and 5.6e22: the rounding tolerance of a cut's line is
// then far wider than the slivers, and while FindOpenings() took every edge within it for an
// edge on the cut, it listed one opening four times, and paired pieces that share no cut (0 and
// 2 of the second input, whose edge runs 1e-21 rad off the cut). Edges on a cut are those the
// cut made, so each shared segment is listed once, between the pieces on either side of it.
TEST(Decompose2dTest, OpeningsOfSliversAreListedOnce) {
  const std::vector<std::vector<Polygon2d>> inputs = {
      FuzzRegressionInput("regression-zero-area-component.wkt"),
      FuzzRegressionInput("regression-vertex-near-split-edge.wkt")};
  for (const std::vector<Polygon2d>& input : inputs) {
    for (const ConcavityMeasure measure : kMeasures) {
      Decompose2dOptions options;
      options.measure = measure;
      options.tau = 0.0;
      const Decomposition2d d = Decompose2d(input, options);
      EXPECT_TRUE(CheckDecomposition(input, d).ok()) << ToString(measure);
      std::set<std::pair<int, int>> pairs;
      for (const Opening2d& opening : d.openings) {
        EXPECT_TRUE(pairs.insert({opening.component_a, opening.component_b}).second)
            << ToString(measure) << ": openings between " << opening.component_a << " and "
            << opening.component_b << " listed more than once";
      }
      // Every piece of these lies next to another along its cut, and to no other.
      EXPECT_EQ(d.openings.size(), d.components.size() - 1) << ToString(measure);
    }
  }
}

// At tau = 0 every notch needs a cut, so a diagonal resolving two notches saves a piece and
// outranks every cut resolving one (ResolveOptions::double_resolves_first). texas.poly: CGAL's
// optimal convex partition has 38 pieces; the target is 1.3 x that (51 before the rule, 45 with
// it, for every measure). At tau > 0 the rule is off: the same pieces as the scores alone give.
TEST(Decompose2dTest, ConvexPartitionOfTexasWithinThirtyPercentOfOptimal) {
  const std::vector<Polygon2d> texas = ReadPolygons((kAcd2d / "texas.poly").string());
  for (const ConcavityMeasure measure : kMeasures) {
    Decompose2dOptions options;
    options.measure = measure;
    options.tau = 0.0;
    const Decomposition2d d = Decompose2d(texas, options);
    EXPECT_LE(d.components.size(), 49u) << ToString(measure);
    EXPECT_TRUE(CheckDecomposition(texas, d).ok()) << ToString(measure);
  }
}

TEST(Decompose2dTest, ComponentGraphIsSymmetric) {
  const std::vector<Polygon2d> monkey =
      ReadPolygons((kAcd2d / "nazca" / "nazca_monkey.poly").string());
  const Decomposition2d d = Decompose2d(monkey);
  const std::vector<std::vector<int>> graph = ComponentGraph(d);
  ASSERT_EQ(graph.size(), d.components.size());
  size_t links = 0;
  for (int a = 0; a < static_cast<int>(graph.size()); ++a) {
    EXPECT_TRUE(std::is_sorted(graph[a].begin(), graph[a].end()));
    EXPECT_FALSE(graph[a].empty()) << "component " << a << " is isolated";
    for (int b : graph[a]) {
      EXPECT_NE(a, b);
      EXPECT_TRUE(std::binary_search(graph[b].begin(), graph[b].end(), a))
          << a << " -> " << b << " without " << b << " -> " << a;
      ++links;
    }
  }
  // A decomposition of a simple polygon by diagonals is a tree of pieces: m - 1 adjacencies
  // at least (more where a Steiner cut end meets a piece further along an edge).
  EXPECT_GE(links / 2, d.components.size() - 1);
  for (const Opening2d& opening : d.openings) EXPECT_LT(opening.component_a, opening.component_b);
}

}  // namespace
}  // namespace acdplan::acd
