// Scenario YAML: every error names the file and the key path; the shipped configs load; the
// demo scenario gives the Figure-4 outcome through the whole runner (collision world included).

#include "planning/scenario.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "acd/polygon2d.h"
#include "base/input_error.h"
#include "planning/plan_scenario.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

using acdplan::test::kConfigs;

/// Writes `text` to a scenario file in the process's scratch folder and returns its path.
std::string Write(const std::string& name, const std::string& text) {
  static const test::ScratchDir dir("acdplan_scenario_test");  // Removed when the process ends.
  return dir.Write(name, text);
}

const std::string kWorld = "workspace: {generator: wall_gap, seed: 1}\n";
const std::string kQuery = "start: [2.5, 5]\ngoal: [7.5, 5]\n";

/// The message LoadScenario() throws for `text`; "" if it does not throw.
std::string ErrorOf(const std::string& text) {
  return test::InputErrorOf([&] { LoadScenario(Write("bad.yaml", text)); });
}

TEST(Scenario, ErrorsNameTheKeyPath) {
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {name: PRM, time_limit: fast}\n")
                .find("bad.yaml: planner.time_limit: expected a positive number, got 'fast'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {name: PRM, time_limt: 3}\n")
                .find("planner.time_limt: unknown key"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "colour: red\n").find("bad.yaml: colour: unknown key"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {name: PRN}\n")
                .find("planner.name: unknown planner 'PRN'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "sampler: {name: acd, uniform_share: 2}\n")
                .find("sampler.uniform_share: expected a number in [0, 1], got '2'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "sampler: {name: magic}\n")
                .find("sampler.name: unknown sampler 'magic'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "sampler: {orientation: sideways}\n")
                .find("sampler.orientation: unknown orientation 'sideways'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {name: RRTConnect, samples: 200}\n")
                .find("planner.samples: a sample budget"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {samples: 0}\n")
                .find("planner.samples: expected an integer >= 1, got '0'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + "start: [2.5, x]\ngoal: [7.5, 5]\n")
                .find("start[1]: expected a finite number, got 'x'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + "start: [2.5, 5, 0]\ngoal: [7.5, 5]\n").find("start: expected [x, y]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kQuery).find("workspace: required"), std::string::npos);
  EXPECT_NE(ErrorOf("workspace: {generator: wall_gap, passage_width: -1}\n" + kQuery)
                .find("workspace.passage_width: expected a positive number, got '-1'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "robot: {shape: disc}\n")
                .find("robot.radius: required for shape disc"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "acd: {measure: xx}\n").find("acd.measure:"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "seed: -3\n").find("seed: expected an integer >= 0"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: [PRM\n").find("bad.yaml:"), std::string::npos);
}

TEST(Scenario, TypedFieldsAndTauDiag) {
  const Scenario s = LoadScenario(
      Write("typed.yaml", kWorld + kQuery +
                              "acd: {tau_diag: 0.03}\nplanner: {name: RRTConnect, time_limit: 1}\n"
                              "sampler: {name: obstacle_based}\ncollision: {mode: bvh}\n"));
  EXPECT_EQ(s.tau_diag, 0.03);
  EXPECT_EQ(s.planner, PlannerType::kRrtConnect);
  EXPECT_EQ(s.sampler, SamplerType::kObstacleBased);
  EXPECT_EQ(s.collision_mode, collision::CollisionMode::kBvh);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(Scenario, TauRelIsTheOlderSpellingOfTauDiagWithAWarning) {
  const Scenario s =
      LoadScenario(Write("old.yaml", kWorld + kQuery + "acd: {tau_rel: 0.04, measure: sl}\n"));
  EXPECT_EQ(s.tau_diag, 0.04);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("old.yaml: acd.tau_rel: read as tau_diag"), std::string::npos)
      << s.warnings[0];
  EXPECT_NE(ErrorOf(kWorld + kQuery + "acd: {tau_rel: 0.04, tau_diag: 0.02}\n")
                .find("bad.yaml: acd.tau_rel: give tau_diag only"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "acd: {tau_diag: -1}\n")
                .find("bad.yaml: acd.tau_diag: expected a number >= 0, got '-1'"),
            std::string::npos);
}

TEST(Scenario, UnknownNamesListTheKnownOnes) {
  EXPECT_NE(ErrorOf(kWorld + kQuery + "planner: {name: PRN}\n")
                .find("bad.yaml: planner.name: unknown planner 'PRN' (expected one of: PRM, "
                      "PRM_ACD, PRMstar, LazyPRM, RRT, RRTConnect, RRTstar, EST, KPIECE1, "
                      "BKPIECE1, SBL)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "robot: {shape: triangle}\n")
                .find("bad.yaml: robot.shape: unknown robot shape 'triangle' (expected one of: "
                      "point, disc, polygon, mesh)"),
            std::string::npos);
  // A mesh robot is read (3D scenarios, plan3d_test.cpp) but needs its file.
  EXPECT_NE(ErrorOf(kWorld + kQuery + "robot: {shape: mesh}\n")
                .find("bad.yaml: robot.mesh: required for shape mesh (a mesh file)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "robot: {shape: point, radius: 1}\n")
                .find("bad.yaml: robot.radius: only for shape disc"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "collision: {mode: fast}\n")
                .find("bad.yaml: collision.mode: unknown collision mode 'fast' (expected one of: "
                      "bvh, hulls, hulls+exact)"),
            std::string::npos);
}

TEST(Scenario, RepairKeyRepairsTheWorkspaceFileWithWarnings) {
  const std::string dir = std::filesystem::path(Write("x.yaml", "")).parent_path().string();
  std::ofstream(dir + "/tile.wkt") << "POLYGON ((4 4, 6 6, 6 4, 4 5.5, 4 4))";  // a bow tie
  const std::string query = "start: [1, 1]\ngoal: [9, 9]\n";
  EXPECT_NE(ErrorOf("workspace: tile.wkt\n" + query).find("tile.wkt: polygon 0: outer ring is not"),
            std::string::npos);
  const Scenario s =
      LoadScenario(Write("fixed.yaml", "workspace: tile.wkt\nrepair: true\n" + query));
  EXPECT_EQ(s.workspace.obstacles.size(), 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("tile.wkt: polygon 0: repaired: "), std::string::npos)
      << s.warnings[0];
  EXPECT_NE(ErrorOf("workspace: tile.wkt\nrepair: maybe\n" + query)
                .find("bad.yaml: repair: expected true or false, got 'maybe'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "repair: true\n")
                .find("bad.yaml: repair: only for a workspace file"),
            std::string::npos);
}

// `unknown: free` reads an occupancy map's unknown cells as free (ROS planners' allow_unknown).
TEST(Scenario, UnknownKeyChoosesHowAMapsUnknownCellsAreRead) {
  const std::string dir = std::filesystem::path(Write("x.yaml", "")).parent_path().string();
  // 3 x 1 pixels: free, unknown (grey 205), occupied.
  std::ofstream(dir + "/grey.pgm") << "P2\n3 1\n255\n254 205 0\n";
  std::ofstream(dir + "/grey.yaml") << "image: grey.pgm\nresolution: 1\norigin: [0, 0, 0]\n";
  const std::string query = "start: [0.5, 0.5]\ngoal: [0.5, 0.5]\n";
  auto blocked_area = [](const Scenario& s) {
    double area = 0.0;
    for (const acd::Polygon2d& obstacle : s.workspace.obstacles) area += acd::Area(obstacle);
    return area;
  };
  EXPECT_EQ(blocked_area(LoadScenario(Write("strict.yaml", "workspace: grey.yaml\n" + query))),
            2.0);
  EXPECT_EQ(blocked_area(
                LoadScenario(Write("free.yaml", "workspace: grey.yaml\nunknown: free\n" + query))),
            1.0);
  EXPECT_NE(ErrorOf("workspace: grey.yaml\nunknown: maybe\n" + query)
                .find("bad.yaml: unknown: unknown unknown-cells rule 'maybe' (expected one of: "
                      "blocked, free)"),
            std::string::npos);
  std::ofstream(dir + "/square.wkt") << "POLYGON ((4 4, 6 4, 6 6, 4 6, 4 4))";
  EXPECT_NE(ErrorOf("workspace: square.wkt\nunknown: free\n" + query)
                .find("bad.yaml: unknown: only for an occupancy map world"),
            std::string::npos);
  EXPECT_NE(ErrorOf(kWorld + kQuery + "unknown: free\n")
                .find("bad.yaml: unknown: only for an occupancy map world (this one is generated)"),
            std::string::npos);
}

TEST(Scenario, StartInCollisionIsAnInputError) {
  const Scenario s = LoadScenario(Write("wall.yaml", kWorld + "start: [5.0, 8.0]\ngoal: [7.5, 5]\n"
                                                              "planner: {samples: 10}\n"));
  try {
    PlanScenario(s);
    FAIL() << "expected acdplan::InputError";
  } catch (const acdplan::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("start: the robot is in collision"), std::string::npos)
        << error.what();
  }
}

TEST(Scenario, ShippedConfigsLoad) {
  for (const char* name :
       {"demo.yaml", "wall_gap.yaml", "wall_gap_se2.yaml", "bug_trap.yaml", "maze.yaml",
        "spiral.yaml", "two_rooms.yaml", "zigzag.yaml", "occupancy_map.yaml"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(LoadScenario(kConfigs + "/" + name));
  }
}

TEST(Scenario, DemoFigure4OutcomeThroughTheRunner) {
  Scenario s = LoadScenario(kConfigs + "/demo.yaml");
  ASSERT_EQ(s.samples, 200);
  int acd = 0, uniform = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    s.seed = seed;
    s.sampler = SamplerType::kAcd;
    const PlanResult a = PlanScenario(s);
    EXPECT_EQ(a.samples, 200u);
    if (a.solved) {
      ++acd;
      EXPECT_GT(a.path.size(), 2u);
      EXPECT_GT(a.path_length, 5.0 - 1e-9);
    }
    s.sampler = SamplerType::kUniform;
    uniform += PlanScenario(s).solved;
  }
  EXPECT_GE(acd, 9);
  EXPECT_LE(uniform, 1);
}

TEST(Scenario, SameSeedSameResult) {
  Scenario s = LoadScenario(kConfigs + "/demo.yaml");
  s.seed = 4;
  const PlanResult a = PlanScenario(s);
  const PlanResult b = PlanScenario(s);
  EXPECT_EQ(a.solved, b.solved);
  EXPECT_EQ(a.collision_checks, b.collision_checks);
  EXPECT_EQ(a.path, b.path);
}

}  // namespace
}  // namespace acdplan::planning
