#include "envs/ompl_app_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "acd/polygon2d.h"
#include "base/input_error.h"
#include "envs/mesh_footprint.h"
#include "tests/data_paths.h"
#include "tests/envs/test_util.h"
#include "tests/input_error_of.h"

namespace acdplan::envs {
namespace {

using testing::TempDir;

const std::string kData = acdplan::test::SourceDir() + "/tests/data/ompl_app/";

/// The message of the InputError that ReadOmplAppProblem(path) throws ("" if none).
std::string ErrorOf(const std::string& path) {
  return test::InputErrorOf([&] { ReadOmplAppProblem(path); });
}

/// A small closed tetrahedron, for inline fixtures.
const char* const kTetra =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

/// A valid 2D [problem] section after `extra` lines, meshes in the temp folder.
std::string Planar(const std::string& extra) {
  return "[problem]\n" + extra +
         "robot=tetra.obj\nworld=tetra.obj\nstart.x=0\nstart.y=0\nstart.theta=0\n"
         "goal.x=1\ngoal.y=1\ngoal.theta=0\n";
}

TEST(ReadOmplAppProblem, ReadsEveryKeyOfA2dProblem) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "planar.cfg");
  EXPECT_EQ(p.name, "planar_fixture");
  EXPECT_EQ(p.dimension, 2);
  EXPECT_EQ(p.robot_path, kData + "meshes/plate_robot.obj");
  EXPECT_EQ(p.world_path, kData + "meshes/walls2d.obj");
  EXPECT_TRUE(p.start.translation().isApprox(Eigen::Vector3d(0, 6, 0)));
  EXPECT_TRUE(p.start.linear().isIdentity(1e-12));
  EXPECT_TRUE(p.goal.translation().isApprox(Eigen::Vector3d(8, 0, 0)));
  // theta is the yaw: x turns into y.
  EXPECT_TRUE((p.goal.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(p.bounds_from_file);
  EXPECT_TRUE(p.bounds.min().isApprox(Eigen::Vector3d(-3, -3, 0)));
  EXPECT_TRUE(p.bounds.max().isApprox(Eigen::Vector3d(10, 9, 0)));
  EXPECT_EQ(p.sampler, "bridge");  // OMPL.app's bridge_test
  EXPECT_EQ(p.objective, "length");
  EXPECT_EQ(p.objective_threshold, 20);
  EXPECT_EQ(p.goal_threshold, 0.001);
  EXPECT_EQ(p.time_limit, 2.5);
  EXPECT_EQ(p.mem_limit, 1000);
  EXPECT_EQ(p.run_count, 7);

  // OMPL.app's planner rules: `rrtconnect.range=50` makes the first copy, `rrtconnect=` a
  // second, which the next range sets; `problem.sampler` goes to the copy before it.
  ASSERT_EQ(p.planners.size(), 4u);
  EXPECT_EQ(p.planners[0].ompl_app_name, "rrtconnect");
  EXPECT_EQ(p.planners[0].planner, "RRTConnect");
  ASSERT_EQ(p.planners[0].parameters.size(), 1u);
  EXPECT_EQ(p.planners[0].parameters[0], std::make_pair(std::string("range"), std::string("50")));
  EXPECT_EQ(p.planners[0].line, 31);
  EXPECT_EQ(p.planners[1].planner, "RRTConnect");
  ASSERT_EQ(p.planners[1].parameters.size(), 1u);
  EXPECT_EQ(p.planners[1].parameters[0].second, "100");
  EXPECT_EQ(p.planners[2].planner, "PRM");
  ASSERT_EQ(p.planners[2].context.size(), 1u);
  EXPECT_EQ(p.planners[2].context[0],
            std::make_pair(std::string("sampler"), std::string("obstacle_based")));
  ASSERT_EQ(p.planners[2].parameters.size(), 1u);
  EXPECT_EQ(p.planners[2].parameters[0], std::make_pair(std::string("name"), std::string("obprm")));
  EXPECT_EQ(p.planners[3].planner, "KPIECE1");
  EXPECT_TRUE(p.planners[3].parameters.empty());

  // Accepted but ignored: a state-space setting and save_paths, each named with its line.
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_NE(p.warnings[0].find("planar.cfg:21: longest_valid_segment_fraction"), std::string::npos)
      << p.warnings[0];
  EXPECT_NE(p.warnings[1].find("planar.cfg:27: benchmark.save_paths"), std::string::npos)
      << p.warnings[1];
}

TEST(ReadOmplAppProblem, ShiftsThePlanarRobotByItsVertexMeanNotItsBoxCentre) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "planar.cfg");
  // Vertices (0,0), (4,0), (4,1), (0,3): mean (2, 1); the box centre would be (2, 1.5).
  EXPECT_TRUE(p.robot_center.isApprox(Eigen::Vector3d(2, 1, 0))) << p.robot_center.transpose();
  const Eigen::AlignedBox3d box = acd::BoundingBox(p.robot);
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(-2, -1, 0)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(2, 2, 0)));
  // The world is not moved.
  EXPECT_TRUE(acd::BoundingBox(p.world).min().isApprox(Eigen::Vector3d(2, 0, 0)));
}

TEST(ReadOmplAppProblem, ReadsA3dProblemAndInfersTheBoundsFromTheWorld) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "spatial.cfg");
  EXPECT_EQ(p.dimension, 3);
  EXPECT_EQ(p.name, "spatial_fixture");
  EXPECT_TRUE(p.start.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  // Axis (0, 0, 2) is normalised as OMPL's setAxisAngle does: a quarter turn about z.
  EXPECT_TRUE((p.start.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(p.goal.translation().isApprox(Eigen::Vector3d(20, -1, 0.5)));
  // A half turn about x flips y and z.
  EXPECT_TRUE(p.goal.linear().isApprox(Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix()));
  EXPECT_EQ(p.sampler, "obstacle_based");
  EXPECT_EQ(p.time_limit, 10);
  EXPECT_EQ(p.run_count, 3);
  EXPECT_LT(p.mem_limit, 0);
  // The COLLADA world's node moves its cube to x = 10; no volume keys: its bounding box.
  EXPECT_FALSE(p.bounds_from_file);
  EXPECT_TRUE(p.bounds.min().isApprox(Eigen::Vector3d(9, -1, -1))) << p.bounds.min().transpose();
  EXPECT_TRUE(p.bounds.max().isApprox(Eigen::Vector3d(11, 1, 1)));
  ASSERT_EQ(p.planners.size(), 2u);
  EXPECT_EQ(p.planners[0].planner, "RRTstar");
  EXPECT_EQ(p.planners[1].planner, "EST");
  EXPECT_EQ(p.planners[1].parameters.size(), 1u);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(ReadOmplAppProblem, ShiftsThe3dRobotByItsVertexMean) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "spatial.cfg");
  // Five vertices: mean (1.6, 1.6, 0.8), box centre (2, 2, 2), volume centroid (1.6, 1.6, 1).
  EXPECT_TRUE(p.robot_center.isApprox(Eigen::Vector3d(1.6, 1.6, 0.8)))
      << p.robot_center.transpose();
  ASSERT_EQ(p.robot.vertices.rows(), 5);
  EXPECT_TRUE(p.robot.vertices.colwise().mean().isZero(1e-12));
}

TEST(OmplAppWorkspace3d, IsTheBoundsAndTheUnmovedWorld) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "spatial.cfg");
  const Workspace3d w = OmplAppWorkspace3d(p);
  EXPECT_TRUE(w.bounds.isApprox(p.bounds));
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_EQ(w.obstacles[0].vertices, p.world.vertices);
  EXPECT_EQ(w.description, "OMPL.app problem spatial_fixture");
}

TEST(ReadOmplAppProblem, ResolvesMeshPathsAgainstTheFilesFolderAndAppliesNodeTransforms) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "sub/relative.cfg");
  EXPECT_EQ(p.robot_path, kData + "meshes/moved_cube.dae");
  EXPECT_EQ(p.world_path, kData + "meshes/walls2d.obj");
  EXPECT_EQ(p.name, "relative");  // the file's stem without a name key
  // The robot's node translates its cube to x = 10; the mean of its vertices is there.
  EXPECT_TRUE(p.robot_center.isApprox(Eigen::Vector3d(10, 0, 0), 1e-6))
      << p.robot_center.transpose();
  EXPECT_TRUE(acd::BoundingBox(p.robot).center().isZero(1e-6));
  EXPECT_TRUE(p.bounds_from_file);
  EXPECT_TRUE(p.bounds.min().isApprox(Eigen::Vector3d(-5, -6, -7)));
  EXPECT_TRUE(p.bounds.max().isApprox(Eigen::Vector3d(5, 6, 7)));
  EXPECT_TRUE(p.planners.empty());
}

TEST(ReadOmplAppProblem, AcceptsAByteOrderMarkWhitespaceCommentsCaseAndCarriageReturns) {
  TempDir dir;
  dir.Write("tetra.obj", kTetra);
  const std::string path = dir.Write(
      "ok.cfg",
      "\xEF\xBB\xBF; a UTF-8 byte order mark, then a comment\r\n\r\n[Problem]\r\n  Name = spaced "
      "name  \r\nrobot = tetra.obj\r\n"
      "start.x = 1 # trailing\r\nstart.y=2\r\nstart.theta=0.5\r\ngoal.x=3\r\ngoal.y=4\r\n"
      "goal.theta=0\r\nvolume.min.x=0\r\nvolume.min.y=0\r\nvolume.max.x=5\r\nvolume.max.y=5\r\n");
  const OmplAppProblem p = ReadOmplAppProblem(path);
  EXPECT_EQ(p.name, "spaced name");
  EXPECT_EQ(p.start.translation().x(), 1.0);
  EXPECT_TRUE(p.world_path.empty());
  EXPECT_EQ(p.world.vertices.rows(), 0);
  EXPECT_EQ(p.sampler, "");
  EXPECT_LT(p.time_limit, 0);
}

TEST(ReadOmplAppProblem, ErrorsNameTheFileTheLineAndTheKey) {
  TempDir dir;
  dir.Write("tetra.obj", kTetra);
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {"[problem]\nrobot\n", "bad.cfg:2: expected 'key=value' or '[section]', got 'robot'"},
      {"[problem\n", "bad.cfg:1: expected '[section]', got '[problem'"},
      {"robot=tetra.obj\n", "bad.cfg:1: robot: outside any section"},
      {"[benchmark]\nrun_count=1\n", "bad.cfg:0: [problem]: missing"},
      {Planar("start.x=2\n"), "bad.cfg:5: start.x: given twice (first on line 2)"},
      {Planar("control=blimp\n"),
       "bad.cfg:2: control: 'blimp' is not supported (acdplan plans kinematic_car and "
       "dynamic_car"},
      {Planar("control=kinematic_car\nstart.z=0\n"), "bad.cfg:"},
      {Planar("control=dynamic car\n") + "[planner]\nprm=\n",
       "bad.cfg:12: unknown planner 'prm' (expected one of: rrt, kpiece, est, pdst, sycloprrt, "
       "syclopest, sst)"},
      {Planar("control=kinematic_car\n") + "[planner]\nsst=\n",
       "bad.cfg:12: planner 'sst' is not available in acdplan (available: rrt, kpiece, est, "
       "pdst, sycloprrt, syclopest)"},
      {Planar("start.z=1\n"),
       "bad.cfg:2: start.axis.x: missing; a 3D problem (start.z is given here)"},
      {"[problem]\nrobot=tetra.obj\nstart.x=0\nstart.y=0\nstart.theta=0\ngoal.x=0\ngoal.y=0\n",
       "bad.cfg:1: goal.theta: missing; a 2D problem needs start and goal x, y, theta"},
      {"[problem]\nrobot=tetra.obj\nstart.x=0\nstart.y=0\nstart.z=0\nstart.theta=0\ngoal.x=0\n",
       "bad.cfg:5: goal.y: missing; a 3D problem (start.z is given on line 5)"},
      {Planar("").replace(Planar("").find("start.x=0"), 9, "start.x=abc"),
       "bad.cfg:4: start.x: expected a number, got 'abc'"},
      {Planar("sampler=random\n"),
       "bad.cfg:2: sampler: unknown sampler 'random' (expected one of: uniform, gaussian, "
       "obstacle_based, max_clearance, bridge_test)"},
      {Planar("") + "[planner]\nprm=\nspars2=\n",
       "bad.cfg:12: planner 'spars2' is not available in acdplan (available: prm, prmstar, "
       "lazyprm, rrt, rrtconnect, rrtstar, est, sbl, kpiece, bkpiece)"},
      {Planar("") + "[planner]\ntrrt.range=3\n",
       "bad.cfg:11: planner 'trrt' is not available in acdplan"},
      {Planar("") + "[planner]\nmagic=\n", "bad.cfg:11: unknown planner 'magic'"},
      {Planar("") + "[planner]\nprm=\nproblem.sampler=best\n",
       "bad.cfg:12: problem.sampler: unknown sampler 'best'"},
      {Planar("volume.min.x=0\nvolume.min.y=0\nvolume.max.x=1\n"),
       "bad.cfg:2: volume.max.y: missing; give every volume.min/max key"},
      {Planar("volume.min.x=2\nvolume.min.y=0\nvolume.max.x=1\nvolume.max.y=1\n"),
       "bad.cfg:4: volume.max.x: expected a number > volume.min.x (2), got 1"},
      {Planar("").replace(Planar("").find("world=tetra.obj\n"), 16, ""),
       "bad.cfg:1: volume.min.x: missing; without a world the volume bounds are required"},
      {Planar("").replace(Planar("").find("robot=tetra.obj"), 15, "robot=nope.obj"),
       "bad.cfg:2: robot: " + dir.Path("nope.obj") + ": cannot read the file"},
      {Planar("").replace(Planar("").find("world=tetra.obj"), 15, "world=gone.dae"),
       "bad.cfg:3: world: " + dir.Path("gone.dae") + ": cannot read the file"},
      {Planar("").replace(Planar("").find("robot=tetra.obj\n"), 16, ""),
       "bad.cfg:1: robot: missing; the robot's mesh file is required"},
      {Planar("") + "[benchmark]\nrun_count=1.5\n",
       "bad.cfg:11: run_count: expected an integer >= 1, got 1.5"},
      {Planar("") + "[benchmark]\ntime_limit=0\n",
       "bad.cfg:11: time_limit: expected a number > 0, got 0"},
      {Planar("") + "[benchmark]\nmem_limit=-1\n",
       "bad.cfg:11: mem_limit: expected a number >= 0, got -1"},
  };
  for (const Case& c : cases) {
    const std::string path = dir.Write("bad.cfg", c.text);
    const std::string message = ErrorOf(path);
    EXPECT_EQ(message.rfind(path, 0), 0u) << c.text << "\n-> " << message;
    EXPECT_NE(message.find(dir.Path(c.expected)), std::string::npos)
        << c.text << "\n-> " << message;
  }
  EXPECT_NE(ErrorOf(dir.Path("missing.cfg")).find(dir.Path("missing.cfg") + ":0: cannot read"),
            std::string::npos);
}

TEST(Footprint, UnitesTheProjectedTrianglesOfAPlanarWorld) {
  const OmplAppProblem p = ReadOmplAppProblem(kData + "planar.cfg");
  const std::vector<acd::Polygon2d> parts = Footprint(p.world, "walls2d.obj");
  ASSERT_EQ(parts.size(), 2u);
  double area = 0;
  for (const acd::Polygon2d& part : parts) {
    EXPECT_EQ(part.outer.size(), 4u);  // the side walls (edge-on) add nothing
    EXPECT_TRUE(part.holes.empty());
    area += acd::Area(part);
  }
  EXPECT_NEAR(area, 1 * 4 + 1 * 4, 1e-12);
  // A slab above the walls sees none of them.
  FootprintOptions above;
  above.z_min = 1.5;
  EXPECT_TRUE(Footprint(p.world, "walls2d.obj", above).empty());
}

TEST(Footprint, SeesZUpCollada2dWorldsInTheXyPlaneAsOmplAppDoes) {
  // assimp turns a Z_UP file to Y_UP, for OMPL.app and ReadMesh alike: the plan drawn in the
  // file's x-z plane lands in the x-y plane, extruded along +z.
  const OmplAppProblem p = ReadOmplAppProblem(kData + "zup_planar.cfg");
  EXPECT_TRUE(acd::BoundingBox(p.world).min().isApprox(Eigen::Vector3d(1, 3, 0)));
  EXPECT_TRUE(acd::BoundingBox(p.world).max().isApprox(Eigen::Vector3d(2, 4, 1)));
  const std::vector<acd::Polygon2d> parts = Footprint(p.world, "zup_box.dae");
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_NEAR(acd::Area(parts[0]), 1.0, 1e-12);
}

TEST(Footprint, KeepsHolesAndFailsForARobotOfSeveralParts) {
  // A square ring of four triangles pairs around a square hole, plus an overlapping cover.
  acd::TriangleMesh ring = acd::MakeTriangleMesh(
      {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}},
      {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}});
  const std::vector<acd::Polygon2d> parts = Footprint(ring, "ring");
  ASSERT_EQ(parts.size(), 1u);
  ASSERT_EQ(parts[0].holes.size(), 1u);
  EXPECT_NEAR(acd::Area(parts[0]), 9 - 1, 1e-12);
  EXPECT_NEAR(acd::Area(FootprintOutline(ring, "ring")), 8, 1e-12);

  const OmplAppProblem p = ReadOmplAppProblem(kData + "planar.cfg");
  try {
    FootprintOutline(p.world, "walls2d.obj");
    FAIL() << "two walls are no robot";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("walls2d.obj: the robot's footprint has 2 separate "
                        "parts"),
              std::string::npos)
        << error.what();
  }
  const acd::Polygon2d robot = FootprintOutline(p.robot, "plate_robot.obj");
  EXPECT_NEAR(acd::Area(robot), (3 + 1) / 2.0 * 4, 1e-12);
}

TEST(OmplAppPlannerTable, MapsEveryEntryToOneOfOurNames) {
  const auto table = OmplAppPlannerTable();
  ASSERT_EQ(table.size(), 10u);
  EXPECT_EQ(table.front(), std::make_pair(std::string("prm"), std::string("PRM")));
  for (const auto& [ompl_app, ours] : table) {
    EXPECT_FALSE(ours.empty()) << ompl_app;
  }
}

}  // namespace
}  // namespace acdplan::envs
