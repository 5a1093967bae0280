// Decompose2d() on GIS-like polygons: a long outer ring, many holes on a grid whose corners
// line up in exact rows (building footprints, lakes in a clipped tile). Each failure found on
// such inputs is kept as a minimal inline fixture; a generated 10^4-vertex, 10^3-hole case
// checks that the whole decomposition stays valid (its time is recorded, never asserted).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/prepare_polygon.h"
#include "base/random.h"
#include "base/stopwatch.h"
#include "tests/asan_build.h"

namespace acdplan::acd {
namespace {

// Decomposes `polygon` at tau = tau_rel x ReferenceRadius() and checks the result.
Decomposition2d DecomposeAndCheck(const Polygon2d& polygon, double tau_rel,
                                  ConcavityMeasure measure = ConcavityMeasure::kShortestPath) {
  const std::vector<Polygon2d> input = PreparePolygons(polygon, "gis");
  Decompose2dOptions options;
  options.tau = tau_rel * ReferenceRadius(polygon);
  options.measure = measure;
  const Decomposition2d decomposition = Decompose2d(input, options);
  const DecompositionCheck check = CheckDecomposition(input, decomposition);
  EXPECT_TRUE(check.ok()) << check.problems.front();
  return decomposition;
}

// Shrunk from the 1,024-hole tile (jitter (0, 0.5)): several holes have a corner at exactly
// y = 11, y = 21, ... A hole's first cut ran from (55.34, 11) left to a point constructed on the
// outer edge x = 0; rounded to y = 11 - 4e-15 it slipped under the corners on its row, which
// exact signs on the rounded point accept, and left a piece pinched to 1e-15 that no cut could
// resolve ("could not resolve a piece with 8 vertices and concavity 4.17832").
TEST(Decompose2dGisTest, CutAlongARowOfHoleCornersKeepsClearOfThem) {
  const Polygon2d polygon{{{0, 0}, {80, 0}, {77.599999999999994, 82}, {17.600000000000001, 82}},
                          {{{24.344844829765201, 21},
                            {28.577818699059769, 25.173501236068766},
                            {24.480782766797557, 27.551781783231135}},
                           {{25.224228178577647, 31},
                            {28.502488567126736, 35.380572483109638},
                            {25.72378959333086, 37.918318360476846}},
                           {{31.154707424350285, 35},
                            {38.917827980052714, 35.367991970159459},
                            {34.730497035460928, 37.661308458062081}},
                           {{34.948271889340553, 41},
                            {38.852777708760485, 45.043744101223169},
                            {35.044043914976193, 47.763384267440841}},
                           {{34.65410647552244, 51},
                            {38.629012981525094, 55.43792517033998},
                            {35.096946157458163, 57.99091335842634}},
                           {{34.661176581915733, 61},
                            {38.58568214814121, 65.04172786660861},
                            {34.8346222391284, 67.748785142348055}},
                           {{35.475850441537581, 71},
                            {38.771938761196409, 75.116065935644457},
                            {35.50126391686932, 77.644310625327748}},
                           {{41.379412532450942, 35},
                            {48.804023551176748, 35.468549946674003},
                            {44.85391528312811, 37.724431365090886}},
                           {{55.338252212045404, 11},
                            {58.533710376042634, 15.00570446854123},
                            {55.670580514593496, 17.998188639279689}},
                           {{51.185501676090276, 25},
                            {54.314144885705389, 21},
                            {58.511698857428499, 25.462930739186103}},
                           {{51.083601809874018, 35},
                            {58.508120973297942, 35.186348574003112},
                            {54.680581898201659, 37.554451565588877}},
                           {{61.209755438086823, 25},
                            {65.171809990458343, 21},
                            {68.606447601808, 25.185444353710754},
                            {65.20795285175636, 27.8044423750646}},
                           {{61.348042078517878, 35},
                            {68.663409063459085, 35.180301756530653},
                            {65.051936604433763, 37.950054134770681}},
                           {{71.176054726558164, 15},
                            {78.670814328833202, 15.20972614501253},
                            {74.434005176355285, 17.523516422586297}},
                           {{71.41633839794531, 25},
                            {74.694115510534914, 21},
                            {78.688459667128811, 25.394658805160599},
                            {74.882447899619905, 27.845254092266117}},
                           {{71.042951213358634, 35},
                            {78.817570406674491, 35.439608120905987},
                            {75.640947774594181, 37.607965697034722}}}};
  DecomposeAndCheck(polygon, 0.01);
}

// Shrunk from a 100-hole tile (jitter (0, 1)): corners in exact rows again (y = 21, 25, 35).
// A hole cut from the corner (4.59, 21) to a point constructed on an earlier cut, rounded to
// y = 21 - 4e-15, slipped under the corner (15.16, 21); a later cut then ran from that corner
// to a point constructed 2e-15 away from it, and the piece between came out with a vertex on
// its own edge ("component 21: not simple: edges (0,1) and (3,4) touch at (15.1575180334,
// 21)"), the CheckDecomposition() failure of the 13k-vertex tile.
TEST(Decompose2dGisTest, CutThroughAHoleCornerIsNotTaken) {
  const Polygon2d polygon{{{0, 0},
                           {100, 0},
                           {95.666666666666671, 103.41841602055266},
                           {18.666666666666671, 102},
                           {0, 102}},
                          {{{1.8637701958858752, 15},
                            {8.7388596598605801, 15.370902214300846},
                            {5.6346482088451468, 17.066147755589906}},
                           {{4.588533736569806, 21},
                            {8.4411004667564562, 25.2498862332565},
                            {4.9441151257010896, 27.976567910013703}},
                           {{1.2095977076327082, 35},
                            {5.5332815630807506, 31},
                            {8.0648709801402259, 35.58104733048205}},
                           {{6.1981467409267204, 61},
                            {8.4261267293578257, 65.750839031845956},
                            {6.5814192893877408, 67.627061491199811}},
                           {{11.542765537772842, 25},
                            {15.157518033374211, 21},
                            {18.736885826229617, 25.305837424333085}},
                           {{11.408992207541388, 35},
                            {18.589582312788281, 35.60816895095499},
                            {16.398122441385603, 37.920633712192497}},
                           {{15.212964129258879, 61},
                            {18.116713174020575, 65.968906753051272},
                            {15.526870613219845, 67.054883484642943}},
                           {{16.06199897922459, 71},
                            {18.730265740583935, 75.377559949012536},
                            {16.289841418487438, 77.762091146874923}},
                           {{21.418826800757252, 25},
                            {26.769325613226592, 21},
                            {28.577447746671265, 25.108330729975393},
                            {27.342943888548909, 27.397790413103341}},
                           {{21.304652755877509, 35},
                            {28.92872655149424, 35.42877537263184},
                            {26.555731205649501, 37.760574222173531}},
                           {{31.276073327034169, 25},
                            {38.735886858192956, 25.515751655803868},
                            {37.599655825982936, 27.37026928501912}},
                           {{36.474457159504539, 91},
                            {38.672684926601619, 95.604468051585684},
                            {37.439342476423867, 97.161508236275793}},
                           {{45.466781436940039, 11},
                            {48.693746908251086, 15.794699715509354},
                            {45.500837210163958, 17.783721024921835}},
                           {{41.437663947182834, 35},
                            {46.048160967672658, 31},
                            {48.77922749015223, 35.110982086348606},
                            {46.576444420552207, 37.894826170347883}},
                           {{41.383615356354213, 45},
                            {46.643676659684239, 41},
                            {48.970373017823597, 45.130040418319133}},
                           {{45.857415533710032, 51},
                            {48.591613334589894, 55.95141596916114},
                            {46.104436874198242, 57.403182588771358}},
                           {{81.061073173806363, 85},
                            {88.231720220272621, 85.137491445223375},
                            {87.138123977770931, 87.392484286146768}},
                           {{95.399565937803658, 1},
                            {98.699474134505465, 5.7937283515873608},
                            {96.37798294468044, 7.2347006243615857}},
                           {{95.840206058654715, 31},
                            {98.493888221543799, 35.442952954386222},
                            {95.863516488743102, 37.871571523078472}}}};
  DecomposeAndCheck(polygon, 0.01);
}

// A map tile: a square whose top side is a saw tooth of `teeth` vertices, and grid x grid
// diamond holes (cell 10) whose corners are jittered by up to `jitter`; the bottom corner of
// every hole in a row sits at the same y, as axis-aligned footprints do.
Polygon2d GisTile(int grid, int teeth, double jitter, std::uint64_t seed) {
  RandomEngine rng(seed);
  constexpr double kCell = 10.0;
  const double size = grid * kCell;
  Polygon2d polygon;
  polygon.outer = {{0, 0}, {size, 0}};
  for (int i = 0; i <= teeth; ++i) {
    const double x = size - size * i / teeth;
    polygon.outer.emplace_back(x, size + 2.0 + (i % 2 == 0 ? 0.0 : UniformReal(rng, 0.0, 2.0)));
  }
  auto wiggle = [&] { return UniformReal(rng, 0.0, jitter); };
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      const double x = i * kCell, y = j * kCell;
      const double right = x + kCell - 1.0 - wiggle();
      const double left = x + 1.0 + wiggle();
      const double mid = left + (right - left) * (0.4 + wiggle() / 2.5);
      polygon.holes.push_back({{left, y + 5},
                               {mid, y + 1},
                               {right, y + 5 + wiggle()},
                               {mid + wiggle(), y + 8 - wiggle()}});
    }
  }
  return polygon;
}

TEST(Decompose2dGisTest, LargeTileDecomposesAndPassesCheckDecomposition) {
#if ACDPLAN_ASAN_BUILD
  const int grid = 10, teeth = 1000;  // 10^3 vertices, 10^2 holes.
#else
  const int grid = 32, teeth = 9000;  // 1.3 x 10^4 vertices, 1,024 holes.
#endif
  const Polygon2d polygon = GisTile(grid, teeth, 0.5, 7);
  for (const ConcavityMeasure measure :
       {ConcavityMeasure::kShortestPath, ConcavityMeasure::kStraightLine}) {
    const Stopwatch stopwatch;
    const Decomposition2d decomposition = DecomposeAndCheck(polygon, 0.01, measure);
    const std::string name = ToString(measure);
    RecordProperty(name + "_decompose_and_check_ms", std::to_string(stopwatch.Milliseconds()));
    RecordProperty(name + "_decompose_ms", std::to_string(decomposition.stats.time_ms));
    RecordProperty(name + "_components", static_cast<int>(decomposition.components.size()));
    EXPECT_GT(decomposition.components.size(), polygon.holes.size());
  }
}

// A warehouse: `rows` x `columns` shelves (10 x 2) with aisles of 2 in a hall with a border of 5,
// turned by `degrees` about the origin.
Polygon2d Warehouse(int rows, int columns, double degrees) {
  constexpr double kLength = 10.0, kWidth = 2.0, kAisle = 2.0, kBorder = 5.0;
  const double radians = degrees * EIGEN_PI / 180.0;
  const double c = std::cos(radians), s = std::sin(radians);
  auto turned = [&](double x, double y) { return Point2d(c * x - s * y, s * x + c * y); };
  const double width = 2 * kBorder + columns * kLength + (columns - 1) * kAisle;
  const double height = 2 * kBorder + rows * kWidth + (rows - 1) * kAisle;
  Polygon2d hall;
  hall.outer = {turned(0, 0), turned(width, 0), turned(width, height), turned(0, height)};
  for (int r = 0; r < rows; ++r) {
    for (int k = 0; k < columns; ++k) {
      const double x = kBorder + k * (kLength + kAisle), y = kBorder + r * (kWidth + kAisle);
      hall.holes.push_back({turned(x, y), turned(x, y + kWidth), turned(x + kLength, y + kWidth),
                            turned(x + kLength, y)});
    }
  }
  return hall;
}

// The hierarchy's depth: its longest path from the root.
int Depth(const Decomposition2d& decomposition) {
  int depth = 0;
  for (const HierarchyNode2d& node : decomposition.tree) depth = std::max(depth, node.depth);
  return depth;
}

// Resolving the witness shelf each time peeled one or two shelves off a piece that kept the
// others, so the hierarchy was about H / 2 deep for H shelves and each level measured what
// remained (quadratic); a piece whose split peels is halved instead, along a row of shelves,
// whichever way the rows run.
TEST(Decompose2dGisTest, WarehouseIsHalvedAlongRowsOfShelvesNotPeeled) {
  for (const double degrees : {0.0, 30.0}) {
    const Polygon2d hall = Warehouse(20, 10, degrees);
    for (const ConcavityMeasure measure :
         {ConcavityMeasure::kShortestPath, ConcavityMeasure::kStraightLine}) {
      const std::string name = ToString(measure) + "_" + std::to_string(static_cast<int>(degrees));
      SCOPED_TRACE(name);
      const Decomposition2d decomposition = DecomposeAndCheck(hall, 0.01, measure);
      RecordProperty(name + "_depth", Depth(decomposition));
      RecordProperty(name + "_components", static_cast<int>(decomposition.components.size()));
      EXPECT_LT(Depth(decomposition), 40);
      for (const Component2d& component : decomposition.components) {
        EXPECT_TRUE(component.polygon.holes.empty());
      }
    }
  }
}

}  // namespace
}  // namespace acdplan::acd
