// libFuzzer target: envs::ReadMovingAiMap() (and ReadMovingAiScenario()) on arbitrary bytes
// written to a file. InputError is the expected answer to bad input; anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding. A map it accepts, up to 32 x 32
// cells, also has its free space traced (FreeSpace2d() of GridWorkspace()), and a wrong free
// space is a finding: a polygon that PreparePolygon() would change, a free cell's centre in no
// polygon or in two, a blocked cell's in one; up to 12 x 12 cells, polygons other than the
// Boolean construction's (by count and area).
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "acd/internal/ring_locator.h"
#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "envs/free_space2d.h"
#include "envs/moving_ai_map.h"
#include "envs/moving_ai_scenario.h"
#include "envs/occupancy_grid.h"
#include "fuzz/fuzz_input.h"

namespace {

using acdplan::acd::Point2d;
using acdplan::acd::Polygon2d;

[[noreturn]] void Finding(const char* what, int row, int column) {
  std::fprintf(stderr, "fuzz_moving_ai_map: %s (cell %d, %d)\n", what, row, column);
  std::abort();
}

void CheckFreeSpace(const acdplan::envs::OccupancyGrid& grid) {
  const acdplan::envs::Workspace2d world = acdplan::envs::GridWorkspace(grid);
  const std::vector<Polygon2d> free = acdplan::envs::FreeSpace2d(world);
  for (const Polygon2d& polygon : free) {
    const Polygon2d again = acdplan::acd::PreparePolygon(polygon, "fuzz");
    if (again.outer != polygon.outer || again.holes != polygon.holes) {
      Finding("PreparePolygon changes a traced polygon", -1, -1);
    }
  }
  const std::vector<acdplan::acd::internal::RingLocator> locators(free.begin(), free.end());
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const Point2d centre =
          grid.origin + grid.resolution * Point2d(c + 0.5, grid.height - r - 0.5);
      int count = 0;
      for (const acdplan::acd::internal::RingLocator& polygon : locators) {
        count += polygon.InsideParity(centre);
      }
      if (count != (grid.Blocked(r, c) ? 0 : 1)) Finding("a cell in the wrong polygons", r, c);
    }
  }
  if (grid.width > 12 || grid.height > 12) return;
  acdplan::envs::Workspace2d slanted = world;  // A slanted edge: the Boolean construction.
  const Point2d far = world.bounds.max() + Point2d(1, 1);
  slanted.obstacles.push_back({{far, far + Point2d(1, 0), far + Point2d(0, 1)}, {}});
  const std::vector<Polygon2d> boolean = acdplan::envs::FreeSpace2d(slanted);
  double area = 0.0, boolean_area = 0.0;
  for (const Polygon2d& polygon : free) area += acdplan::acd::Area(polygon);
  for (const Polygon2d& polygon : boolean) boolean_area += acdplan::acd::Area(polygon);
  if (boolean.size() != free.size() || std::abs(boolean_area - area) > 1e-9 * (1.0 + area)) {
    Finding("the constructions give different polygons", -1, -1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  try {  // The same bytes as a scenario file (.scen) of problems on maps.
    acdplan::envs::ReadMovingAiScenario(acdplan::fuzz::WriteInputFile("fuzz.scen", text));
  } catch (const acdplan::InputError&) {
  }
  const std::string path = acdplan::fuzz::WriteInputFile("fuzz.map", text);
  acdplan::envs::OccupancyGrid grid;
  try {
    grid = acdplan::envs::ReadMovingAiMap(path);
  } catch (const acdplan::InputError&) {
    return 0;
  }
  if (grid.width <= 32 && grid.height <= 32) CheckFreeSpace(grid);
  return 0;
}
