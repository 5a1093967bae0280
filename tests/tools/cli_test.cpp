// Runs the built `acdplan` binary (test::AcdplanBinary()) and checks exit statuses, messages and
// outputs of `acdplan decompose` (polygons and meshes) and `acdplan env`.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/data_paths.h"
#include "tests/scratch_dir.h"

namespace {

namespace fs = std::filesystem;

const std::string kPolygons = acdplan::test::DataDir() + "/polygons/acd2d/";
const std::string kMeshes = acdplan::test::DataDir() + "/meshes/vhacd/";
const std::string kSource = acdplan::test::SourceDir() + "/";

struct RunResult {
  int status = -1;
  std::string out, err;
};

std::string Read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string Quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

class CliTest : public ::testing::Test {
 protected:
  RunResult Acdplan(const std::string& arguments) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = Quote(acdplan::test::AcdplanBinary()) + " " + arguments + " >" +
                                Quote(out.string()) + " 2>" + Quote(err.string());
    const int raw = std::system(command.c_str());
    RunResult run;
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = Read(out);
    run.err = Read(err);
    fs::remove(out);
    fs::remove(err);
    return run;
  }

  int FileCount() const {
    int n = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) n += entry.is_regular_file();
    return n;
  }

  fs::path Write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  acdplan::test::ScratchDir scratch_{"acdplan_cli_test"};
  fs::path dir_ = scratch_.path();
};

/// Exactly one line on stderr, "acdplan: error: ...".
void ExpectUsageError(const RunResult& run) {
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.err.rfind("acdplan: error: ", 0), 0u) << run.err;
  ASSERT_FALSE(run.err.empty());
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

TEST_F(CliTest, VersionAndHelp) {
  RunResult run = Acdplan("--version");
  EXPECT_EQ(run.status, 0);
  EXPECT_NE(run.out.find(ACDPLAN_VERSION), std::string::npos) << run.out;
  run = Acdplan("decompose --help");
  EXPECT_EQ(run.status, 0);
  EXPECT_NE(run.out.find("--tau-rel"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("largest radius"), std::string::npos) << run.out;
}

TEST_F(CliTest, MissingFileNamesTheFile) {
  const std::string missing = (dir_ / "no_such_polygon.poly").string();
  const RunResult run = Acdplan("decompose " + Quote(missing));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
}

TEST_F(CliTest, UnknownExtensionListsThePolygonAndMeshFormats) {
  const std::string input = Write("points.xyz", "0 0 0\n").string();
  const RunResult run = Acdplan("decompose " + Quote(input));
  ExpectUsageError(run);
  EXPECT_NE(
      run.err.find(
          input + ": unknown file extension '.xyz' (expected a polygon file, "
                  ".poly, .wkt, .geojson, .json, .shp, .gpkg, .kml or .kmz, or a mesh, .obj, .off, "
                  ".ply, .stl, or a format assimp reads (.dae, .gltf, .glb, "
                  ".fbx,"),
      std::string::npos)
      << run.err;
}

TEST_F(CliTest, MalformedNumberNamesTheLine) {
  const RunResult run = Acdplan("decompose " + Quote(kPolygons + "bird.poly") + " --json " +
                                Quote((dir_ / "bird.json").string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("bird.poly:47"), std::string::npos) << run.err;
  EXPECT_EQ(FileCount(), 0);  // nothing written
}

TEST_F(CliTest, TauAndTauRelAreMutuallyExclusive) {
  ExpectUsageError(
      Acdplan("decompose " + Quote(kPolygons + "simple1.poly") + " --tau 1 --tau-rel 0.1"));
}

TEST_F(CliTest, UnknownMeasureIsAUsageError) {
  const RunResult run =
      Acdplan("decompose " + Quote(kPolygons + "simple1.poly") + " --measure xyz");
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("xyz"), std::string::npos) << run.err;
}

TEST_F(CliTest, OutOfRangeValuesAreUsageErrors) {
  const std::string input = Quote(kPolygons + "simple1.poly");
  ExpectUsageError(Acdplan("decompose " + input + " --tau -1"));
  ExpectUsageError(Acdplan("decompose " + input + " --tau-rel -0.5"));
  ExpectUsageError(Acdplan("decompose " + input + " --min-convexity 0"));
  ExpectUsageError(Acdplan("decompose " + input + " --min-convexity 1.5"));
  ExpectUsageError(Acdplan("decompose " + input + " --hole-diameter wide"));
  ExpectUsageError(Acdplan("decompose " + input + " --json " + Quote(dir_.string())));
  ExpectUsageError(Acdplan("decompose"));
  ExpectUsageError(Acdplan(""));
  EXPECT_EQ(FileCount(), 0);
}

TEST_F(CliTest, DecomposesAndWritesJsonAndSvg) {
  const fs::path json_path = dir_ / "out" / "simple1.json";
  const fs::path svg_path = dir_ / "out" / "simple1.svg";
  const RunResult run = Acdplan("decompose " + Quote(kPolygons + "simple1.poly") +
                                " --tau-rel 0.05 --measure sl --check --json " +
                                Quote(json_path.string()) + " --svg " + Quote(svg_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  EXPECT_NE(run.out.find("components"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(json_path.string()), std::string::npos) << run.out;
  ASSERT_TRUE(fs::exists(json_path));
  ASSERT_TRUE(fs::exists(svg_path));
  EXPECT_EQ(FileCount(), 2);  // no temporary files left

  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(j.at("format"), "acdplan.decomposition2d/1");
  EXPECT_EQ(j.at("measure"), "sl");
  EXPECT_EQ(j.at("tau_rel").get<double>(), 0.05);
  EXPECT_GE(j.at("components").size(), 1u);
  EXPECT_EQ(j.at("stats").at("components").get<size_t>(), j.at("components").size());

  const std::string svg = Read(svg_path);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("simple1.poly"), std::string::npos);
}

// A GeoPackage layer named as QGIS shows its source: decomposed and checked, its components
// carrying their county's attributes.
TEST_F(CliTest, DecomposesAGeoPackageLayerNamedAsQgisNamesIt) {
  const fs::path geojson_path = dir_ / "nc_gpkg.geojson";
  const RunResult run =
      Acdplan("decompose " +
              Quote((acdplan::test::kGeoPackages / "nc.gpkg").string() + "|layername=nc.gpkg") +
              " --tau-rel 0.05 --measure sl --check --geojson " + Quote(geojson_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("check          ok"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("layer 'nc.gpkg': geographic coordinates (GEOGCS \"NAD27\")"),
            std::string::npos)
      << run.err;
  const nlohmann::json layer = nlohmann::json::parse(Read(geojson_path));
  ASSERT_FALSE(layer.at("features").empty());
  for (const nlohmann::json& feature : layer.at("features")) {
    EXPECT_TRUE(feature.at("properties").at("NAME").is_string());
  }
  const RunResult points =
      Acdplan("decompose " + Quote((acdplan::test::kGeoPackages / "b_pump.gpkg").string()));
  EXPECT_EQ(points.status, 2);
  EXPECT_NE(points.err.find("no layer of polygons"), std::string::npos) << points.err;
}

// A GIS user's round: a shapefile in, a GeoJSON polygon layer out whose components carry their
// county's attributes (from nc.dbf), which acdplan reads back as polygons, and the openings
// between them as a line layer.
TEST_F(CliTest, DecomposesAShapefileIntoGeoJsonWithTheDbfAttributes) {
  const fs::path geojson_path = dir_ / "nc.geojson";
  const fs::path openings_path = dir_ / "nc_openings.geojson";
  const fs::path json_path = dir_ / "nc.json";
  const RunResult run = Acdplan(
      "decompose " + Quote((acdplan::test::kShapefiles / "nc.shp").string()) +
      " --tau-rel 0.05 --measure sl --json " + Quote(json_path.string()) + " --geojson " +
      Quote(geojson_path.string()) + " --openings-geojson " + Quote(openings_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  // nc.prj declares longitude/latitude: one warning.
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("nc.prj: geographic coordinates"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find(geojson_path.string()), std::string::npos) << run.out;
  const nlohmann::json decomposition = nlohmann::json::parse(Read(json_path));
  const nlohmann::json layer = nlohmann::json::parse(Read(geojson_path));
  EXPECT_EQ(layer.at("type"), "FeatureCollection");
  const nlohmann::json& features = layer.at("features");
  ASSERT_EQ(features.size(), decomposition.at("components").size());
  std::vector<bool> county_seen(100, false);
  for (size_t k = 0; k < features.size(); ++k) {
    const nlohmann::json& properties = features[k].at("properties");
    const int county = properties.at("acd_feat").get<int>();
    ASSERT_GE(county, 0);
    ASSERT_LT(county, 100);
    county_seen[static_cast<size_t>(county)] = true;
    EXPECT_EQ(county, decomposition.at("components")[k].at("input_feature"));
    EXPECT_EQ(properties.at("acd_id"), k);
    EXPECT_TRUE(properties.at("NAME").is_string());
    if (county == 0) {
      EXPECT_EQ(properties.at("NAME"), "Ashe");
    }
  }
  EXPECT_EQ(std::count(county_seen.begin(), county_seen.end(), true), 100);

  // The openings, as the JSON has them (counties that share a border meet along seams too).
  const nlohmann::json lines = nlohmann::json::parse(Read(openings_path));
  EXPECT_EQ(lines.at("acdplan").at("format"), "acdplan.openings2d.geojson/1");
  const nlohmann::json& openings = decomposition.at("openings");
  ASSERT_EQ(lines.at("features").size(), openings.size());
  ASSERT_GT(openings.size(), 100u);
  for (size_t k = 0; k < openings.size(); ++k) {
    const nlohmann::json& line = lines.at("features")[k];
    EXPECT_EQ(line.at("geometry").at("type"), "LineString");
    EXPECT_EQ(line.at("geometry").at("coordinates"),
              nlohmann::json::array({openings[k].at("a"), openings[k].at("b")}));
    EXPECT_EQ(line.at("properties").at("acd_id"), k);
    EXPECT_EQ(line.at("properties").at("acd_a"), openings[k].at("components")[0]);
    EXPECT_EQ(line.at("properties").at("acd_b"), openings[k].at("components")[1]);
  }

  // Read back as input: one polygon per component.
  const RunResult again = Acdplan("decompose " + Quote(geojson_path.string()) + " --tau-rel 1");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find(std::to_string(features.size()) + " polygons"), std::string::npos)
      << again.out;
}

TEST_F(CliTest, EnvReportsA2dWorldAndDrawsItsDecomposition) {
  const fs::path json_path = dir_ / "wall_gap.json", svg_path = dir_ / "wall_gap.svg";
  const RunResult run = Acdplan("env " + Quote(kSource + "envs/2d/wall_gap.yaml") + " --json " +
                                Quote(json_path.string()) + " --svg " + Quote(svg_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("(workspace)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("narrowest gap"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(j.at("format"), "acdplan.env/1");
  EXPECT_EQ(j.at("dimension"), 2);
  EXPECT_EQ(j.at("free_regions"), 1);
  // The wall splits the free space in two sides joined through the gap: at least two
  // components and an opening in the gap, narrower than the world.
  EXPECT_GE(j.at("components").get<int>(), 2);
  EXPECT_GE(j.at("openings").get<int>(), 1);
  EXPECT_LT(j.at("narrowest_opening").get<double>(), 0.5 * j.at("bounds")[2].get<double>());
  const std::string svg = Read(svg_path);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("id=\"openings\""), std::string::npos);
  EXPECT_NE(svg.find("<line"), std::string::npos);
  EXPECT_NE(svg.find("id=\"obstacles\""), std::string::npos);
}

TEST_F(CliTest, EnvLoadsEveryKindOfWorld) {
  const fs::path grid =
      Write("grid.map", "type octile\nheight 3\nwidth 5\nmap\n.....\n.@@@.\n.....\n");
  const fs::path world3d = Write("world3d.yaml",
                                 "bounds: [-2, -2, -2, 2, 2, 2]\nobstacles:\n"
                                 "  - mesh: " +
                                     kMeshes +
                                     "box-thick.obj\n"
                                     "    scale: 0.01\n    translation: [-3.7, -0.34, 0]\n");
  const struct {
    std::string file, kind;
    int dimension;
  } worlds[] = {
      {kSource + "envs/2d/maze.yaml", "(workspace)", 2},
      {kSource + "configs/maps/room_door.yaml", "(occupancy map)", 2},
      {grid.string(), "(Moving AI map)", 2},
      {kPolygons + "simple1.poly", "(polygon file)", 2},
      {kSource + "configs/wall_gap_se2.yaml", "(scenario", 2},
      {kMeshes + "box-thick.obj", "(mesh)", 3},
      {world3d.string(), "(3D workspace)", 3},
      {kSource + "configs/window_wall_3d.yaml", "(scenario", 3},
  };
  setenv("ACDPLAN_CACHE_DIR", (dir_ / "cache").c_str(), 1);  // Not the user's cache.
  for (const auto& world : worlds) {
    const fs::path json_path = dir_ / "report.json";
    const RunResult run =
        Acdplan("env " + Quote(world.file) + " --json " + Quote(json_path.string()));
    ASSERT_EQ(run.status, 0) << world.file << "\n" << run.err;
    EXPECT_NE(run.out.find(world.kind), std::string::npos) << run.out;
    const nlohmann::json j = nlohmann::json::parse(Read(json_path));
    EXPECT_EQ(j.at("dimension"), world.dimension) << world.file;
    EXPECT_GE(j.at("obstacles").get<int>(), 1) << world.file;
    EXPECT_GE(j.at("obstacle_hulls").get<int>(), 1) << world.file;
    EXPECT_GE(j.at("components").get<int>(), 1) << world.file;
  }
  unsetenv("ACDPLAN_CACHE_DIR");
}

TEST_F(CliTest, EnvReportsThe3dFreeSpaceAcdOfAScenario) {
  // The window is the one opening between the two sides of the wall (configs/README.md).
  setenv("ACDPLAN_CACHE_DIR", (dir_ / "cache").c_str(), 1);
  const fs::path json_path = dir_ / "report.json";
  const RunResult run = Acdplan("env " + Quote(kSource + "configs/window_wall_3d.yaml") +
                                " --json " + Quote(json_path.string()));
  unsetenv("ACDPLAN_CACHE_DIR");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("solid ACD: 2 components, 1 opening"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("robot            mesh, 12 triangles"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(j.at("dimension"), 3);
  EXPECT_EQ(j.at("openings"), 1);
  EXPECT_NEAR(j.at("narrowest_opening").get<double>(), 1.0, 1e-9);  // The window's side.
  EXPECT_NEAR(j.at("free_volume").get<double>(), 1000.0 - 0.5 * (100 - 1), 1e-9);
  EXPECT_EQ(j.at("robot"), "mesh");
}

TEST_F(CliTest, EnvErrorsNameTheFileAndTheRule) {
  const std::string missing = (dir_ / "no_such_world.yaml").string();
  RunResult run = Acdplan("env " + Quote(missing));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;

  const fs::path bad_key = Write("bad.yaml", "bounds: [0, 0, 1, 1]\nobstacle: []\n");
  run = Acdplan("env " + Quote(bad_key.string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("obstacle"), std::string::npos) << run.err;

  run = Acdplan("env " + Quote(kMeshes + "box-thick.obj") + " --svg " +
                Quote((dir_ / "box.svg").string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("2D worlds only"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "box.svg"));

  ExpectUsageError(Acdplan("env " + Quote(kSource + "envs/2d/maze.yaml") + " --measure xyz"));
}

TEST_F(CliTest, TheSameErrorReadsTheSameInEveryCommand) {
  // A missing file, to decompose, env and plan alike.
  for (const std::string& command :
       {std::string("decompose"), std::string("env"), std::string("plan")}) {
    const std::string missing =
        (dir_ / (command == "decompose" ? "none.poly" : "none.yaml")).string();
    const RunResult run = Acdplan(command + " " + Quote(missing));
    ExpectUsageError(run);
    EXPECT_NE(run.err.find(missing + ": cannot read the file: No such file or directory"),
              std::string::npos)
        << command << ": " << run.err;
  }
  // An unknown name lists the known ones the same way.
  const RunResult planner =
      Acdplan("plan " + Quote(kSource + "configs/demo.yaml") + " --planner PRN");
  ExpectUsageError(planner);
  EXPECT_NE(planner.err.find("unknown planner 'PRN' (expected one of: PRM, PRM_ACD,"),
            std::string::npos)
      << planner.err;
  const RunResult measure =
      Acdplan("env " + Quote(kSource + "envs/2d/maze.yaml") + " --measure xyz");
  EXPECT_NE(measure.err.find("unknown concavity measure 'xyz' (expected one of: sl, sp, h1, h2)"),
            std::string::npos)
      << measure.err;
}

TEST_F(CliTest, EnvReadsTauRelAsTauDiagWithAWarning) {
  const std::string world = Quote(kSource + "envs/2d/wall_gap.yaml");
  const fs::path a = dir_ / "a.json", b = dir_ / "b.json";
  const RunResult diag = Acdplan("env " + world + " --tau-diag 0.05 --json " + Quote(a.string()));
  ASSERT_EQ(diag.status, 0) << diag.err;
  EXPECT_EQ(diag.err, "");
  EXPECT_NE(diag.out.find("tau_diag 0.05 x bounds diagonal"), std::string::npos) << diag.out;
  const RunResult rel = Acdplan("env " + world + " --tau-rel 0.05 --json " + Quote(b.string()));
  ASSERT_EQ(rel.status, 0) << rel.err;
  EXPECT_NE(rel.err.find("warning: --tau-rel is read as --tau-diag"), std::string::npos) << rel.err;
  EXPECT_EQ(nlohmann::json::parse(Read(a)).at("tau_diag"), 0.05);
  EXPECT_EQ(nlohmann::json::parse(Read(a)).at("components"),
            nlohmann::json::parse(Read(b)).at("components"));
}

TEST_F(CliTest, RepairMakesInvalidPolygonsValidAndSaysWhat) {
  const fs::path tile = Write("tile.wkt", "POLYGON ((0 0, 4 4, 4 0, 0 3, 0 0))");  // a bow tie
  for (const std::string& command : {std::string("decompose"), std::string("env")}) {
    const RunResult strict = Acdplan(command + " " + Quote(tile.string()));
    ExpectUsageError(strict);
    EXPECT_NE(strict.err.find("outer ring is not simple"), std::string::npos) << strict.err;
    const RunResult repaired = Acdplan(command + " " + Quote(tile.string()) + " --repair");
    EXPECT_EQ(repaired.status, 0) << command << ": " << repaired.err;
    EXPECT_NE(repaired.err.find("acdplan: " + tile.string() + ": polygon 0: repaired: "),
              std::string::npos)
        << command << ": " << repaired.err;
  }
}

TEST_F(CliTest, DecomposeHoldsMultipolygonMembersDisjoint) {
  // Overlapping members: an error for the region to decompose, fine as obstacles.
  const fs::path tiles =
      Write("tiles.wkt", "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))");
  const RunResult strict = Acdplan("decompose " + Quote(tiles.string()));
  ExpectUsageError(strict);
  EXPECT_NE(strict.err.find("polygons 0 and 1 overlap"), std::string::npos) << strict.err;
  const RunResult repaired = Acdplan("decompose " + Quote(tiles.string()) + " --repair --check");
  EXPECT_EQ(repaired.status, 0) << repaired.err;
  EXPECT_NE(repaired.err.find("polygons 0 and 1: repaired: they overlap"), std::string::npos)
      << repaired.err;
  EXPECT_EQ(Acdplan("env " + Quote(tiles.string())).status, 0);
}

TEST_F(CliTest, DecomposeSkipsPointsAndLinesOfALayerEnvRefusesThem) {
  // A layer to decompose may hold points and lines among its polygons: skipped, with a note.
  // As obstacles, a line may stand for a wall: refused.
  const fs::path site = Write("site.geojson", R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {"kind": "door"},
       "geometry": {"type": "Point", "coordinates": [5, 5]}},
      {"type": "Feature", "properties": {"kind": "hall"},
       "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,4],[2,1],[0,4],[0,0]]]}}]})");
  const fs::path layer = dir_ / "parts.geojson";
  const RunResult run = Acdplan("decompose " + Quote(site.string()) + " --tau 0 --geojson " +
                                Quote(layer.string()) + " --check");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("site.geojson: skipped 1 geometry without area (1 Point; the first at "
                         "features[0].geometry)"),
            std::string::npos)
      << run.err;
  const nlohmann::json parts = nlohmann::json::parse(Read(layer));
  ASSERT_EQ(parts.at("features").size(), 2u);  // The hall, cut at its notch.
  for (const nlohmann::json& part : parts.at("features")) {
    EXPECT_EQ(part.at("properties").at("kind"), "hall");
    EXPECT_EQ(part.at("properties").at("acd_feat"), 1);
  }
  const RunResult env = Acdplan("env " + Quote(site.string()));
  ExpectUsageError(env);
  EXPECT_NE(env.err.find("features[0].geometry: unsupported type 'Point'"), std::string::npos)
      << env.err;
}

// ---- decompose MESH -------------------------------------------------------------------------

/// The OBJ lines of an axis-aligned box [lo, hi], 8 shared vertices numbered from `first`
/// (1-based), 12 triangles counter-clockwise seen from outside; `skip_top` leaves the +z side
/// out (an open box).
std::string BoxObj(const std::array<double, 3>& lo, const std::array<double, 3>& hi, int first = 1,
                   bool skip_top = false) {
  std::ostringstream obj;
  for (int i = 0; i < 8; ++i) {
    obj << "v " << (i & 1 ? hi[0] : lo[0]) << " " << (i & 2 ? hi[1] : lo[1]) << " "
        << (i & 4 ? hi[2] : lo[2]) << "\n";
  }
  // Vertex i has x = bit 0, y = bit 1, z = bit 2.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int q = 0; q < 6; ++q) {
    if (skip_top && q == 1) continue;
    const int* v = quads[q];
    obj << "f " << first + v[0] << " " << first + v[1] << " " << first + v[2] << "\n";
    obj << "f " << first + v[0] << " " << first + v[2] << " " << first + v[3] << "\n";
  }
  return obj.str();
}

TEST_F(CliTest, DecomposesAMeshAndWritesEveryOutput) {
  const fs::path box = Write("box.obj", BoxObj({0, 0, 0}, {2, 1, 1}));
  const fs::path out = dir_ / "out";
  const RunResult run =
      Acdplan("decompose " + Quote(box.string()) + " --tau-rel 0.05 --check --json " +
              Quote((out / "box.json").string()) + " --obj " + Quote((out / "box.obj").string()) +
              " --glb " + Quote((out / "box.glb").string()) + " --svg " +
              Quote((out / "box.svg").string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_NE(run.out.find("8 vertices, 12 triangles"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("defects        none"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solid ACD (closed, manifold, no self-intersections)"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("(tau_rel 0.05 x radius "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("check          ok"), std::string::npos) << run.out;
  for (const char* name : {"box.json", "box.obj", "box.mtl", "box.glb", "box.svg"}) {
    EXPECT_NE(run.out.find((out / name).string()), std::string::npos) << name << "\n" << run.out;
  }

  const nlohmann::json j = nlohmann::json::parse(Read(out / "box.json"));
  EXPECT_EQ(j.at("format"), "acdplan.decomposition3d/1");
  EXPECT_EQ(j.at("input"), box.string());
  EXPECT_EQ(j.at("tau_rel"), 0.05);
  EXPECT_EQ(j.at("stats").at("surface"), false);
  EXPECT_GE(j.at("components").size(), 1u);
  EXPECT_EQ(j.at("stats").at("components").get<size_t>(), j.at("components").size());
  // The box is convex: its components fill it exactly, and so do their hulls.
  EXPECT_NEAR(j.at("stats").at("volume").get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(j.at("stats").at("hull_volume").get<double>(), 2.0, 1e-9);

  const std::string obj = Read(out / "box.obj");
  EXPECT_NE(obj.find("mtllib box.mtl\n"), std::string::npos);
  EXPECT_NE(obj.find("o component_0\n"), std::string::npos);
  EXPECT_NE(obj.find("o hull_0\n"), std::string::npos);
  EXPECT_NE(Read(out / "box.mtl").find("newmtl hull_0\n"), std::string::npos);
  const std::string glb = Read(out / "box.glb");
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(glb.size() % 4, 0u);
  const std::string svg = Read(out / "box.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("solid ACD"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);

  // A mesh reader (assimp, through decompose itself) reads the OBJ and glTF outputs back:
  // every triangle of every component and hull.
  size_t triangles = 0;
  for (const nlohmann::json& c : j.at("components")) {
    triangles += c.at("mesh").at("triangles").size() + c.at("hull").at("triangles").size();
  }
  for (const char* name : {"box.obj", "box.glb"}) {
    const RunResult back = Acdplan("decompose " + Quote((out / name).string()) + " --surface");
    EXPECT_EQ(back.status, 0) << name << ": " << back.err;
    EXPECT_NE(back.out.find(" " + std::to_string(triangles) + " triangles)"), std::string::npos)
        << name << ": " << back.out;
  }
}

TEST_F(CliTest, EveryMeshFormatByItsExtension) {
  // The same box as OFF, ASCII STL and ASCII PLY, and as OBJ with an upper-case extension.
  const std::string obj = BoxObj({0, 0, 0}, {1, 1, 1});
  std::vector<std::string> v, f;
  std::istringstream lines(obj);
  for (std::string line; std::getline(lines, line);) {
    (line[0] == 'v' ? v : f).push_back(line.substr(2));
  }
  std::string off = "OFF\n8 12 0\n";
  for (const std::string& p : v) off += p + "\n";
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty "
      "float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (const std::string& p : v) ply += p + "\n";
  std::string stl = "solid box\n";
  for (const std::string& face : f) {
    std::istringstream ids(face);
    int a = 0, b = 0, c = 0;
    ids >> a >> b >> c;
    off += "3 " + std::to_string(a - 1) + " " + std::to_string(b - 1) + " " +
           std::to_string(c - 1) + "\n";
    ply += "3 " + std::to_string(a - 1) + " " + std::to_string(b - 1) + " " +
           std::to_string(c - 1) + "\n";
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int id : {a, b, c}) stl += "   vertex " + v[id - 1] + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid box\n";
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"box.off", off}, {"box.ply", ply}, {"box.stl", stl}, {"BOX.OBJ", obj}}) {
    const fs::path json_path = dir_ / (name + ".json");
    const RunResult run = Acdplan("decompose " + Quote(Write(name, text).string()) + " --json " +
                                  Quote(json_path.string()));
    ASSERT_EQ(run.status, 0) << name << ": " << run.err;
    EXPECT_NE(run.out.find("solid ACD"), std::string::npos) << name << ": " << run.out;
    const nlohmann::json j = nlohmann::json::parse(Read(json_path));
    EXPECT_EQ(j.at("format"), "acdplan.decomposition3d/1") << name;
    EXPECT_NEAR(j.at("stats").at("volume").get<double>(), 1.0, 1e-6) << name;
  }
}

TEST_F(CliTest, AnOpenMeshGetsTheSurfaceAcd) {
  const fs::path open_box = Write("open_box.obj", BoxObj({0, 0, 0}, {1, 1, 1}, 1, true));
  const fs::path json_path = dir_ / "open_box.json";
  const RunResult run =
      Acdplan("decompose " + Quote(open_box.string()) + " --json " + Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("4 boundary edges"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("surface ACD (open: 4 boundary edges"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(j.at("stats").at("surface"), true);
  EXPECT_GE(j.at("components").size(), 1u);
}

TEST_F(CliTest, SurfaceAcdOfASolidOnRequest) {
  const fs::path box = Write("box.obj", BoxObj({0, 0, 0}, {1, 1, 1}));
  const fs::path json_path = dir_ / "box.json";
  const RunResult run = Acdplan("decompose " + Quote(box.string()) + " --surface --json " +
                                Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("surface ACD (--surface)"), std::string::npos) << run.out;
  EXPECT_EQ(nlohmann::json::parse(Read(json_path)).at("stats").at("surface"), true);
}

TEST_F(CliTest, AClosedNonManifoldMeshNeedsSurfaceOrRepair) {
  // Two cubes sharing one edge (x = 1, y = 1) through shared vertices: closed, but the edge
  // has four faces.
  std::string text = BoxObj({0, 0, 0}, {1, 1, 1});
  std::ostringstream second;
  second << BoxObj({1, 1, 0}, {2, 2, 1}, 9);
  text += second.str();
  const fs::path mesh = Write("edge.obj", text);
  const RunResult strict = Acdplan("decompose " + Quote(mesh.string()) + " --json " +
                                   Quote((dir_ / "edge.json").string()));
  ExpectUsageError(strict);
  EXPECT_NE(strict.err.find(mesh.string() + ": not a solid: "), std::string::npos) << strict.err;
  EXPECT_NE(strict.err.find("use --repair"), std::string::npos) << strict.err;
  EXPECT_NE(strict.err.find("--surface"), std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(dir_ / "edge.json"));
  const RunResult surface = Acdplan("decompose " + Quote(mesh.string()) + " --surface");
  EXPECT_EQ(surface.status, 0) << surface.err;
  EXPECT_NE(surface.out.find("non-manifold edge"), std::string::npos) << surface.out;
}

TEST_F(CliTest, TauMaxHullsMergeGrowthAndTheirDefaults) {
  const fs::path box = Write("box.obj", BoxObj({0, 0, 0}, {1, 1, 1}));
  const fs::path a = dir_ / "a.json", b = dir_ / "b.json";
  RunResult run = Acdplan("decompose " + Quote(box.string()) + " --json " + Quote(a.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("(tau_rel 0.05 x radius "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("the default)"), std::string::npos) << run.out;
  nlohmann::json j = nlohmann::json::parse(Read(a));
  EXPECT_EQ(j.at("tau_rel"), 0.05);
  EXPECT_EQ(j.at("max_hulls"), 0);
  // The default allowance is half of tau_rel.
  EXPECT_NEAR(j.at("merge_growth").get<double>(), 0.025, 1e-12);
  EXPECT_NE(run.out.find("merge          tau-convex neighbours, hull growth <= 0.025"),
            std::string::npos)
      << run.out;

  run = Acdplan("decompose " + Quote(box.string()) +
                " --tau 0.125 --max-hulls 3 --merge-growth -1 --json " + Quote(b.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("max hulls      3"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("merge   "), std::string::npos) << run.out;
  j = nlohmann::json::parse(Read(b));
  EXPECT_EQ(j.at("tau"), 0.125);
  EXPECT_TRUE(j.at("tau_rel").is_null());
  EXPECT_EQ(j.at("max_hulls"), 3);
  EXPECT_TRUE(j.at("merge_growth").is_null());
  EXPECT_LE(j.at("components").size(), 3u);
}

TEST_F(CliTest, MeshErrorsNameTheFileAndTheRule) {
  const std::string box = Quote(Write("box.obj", BoxObj({0, 0, 0}, {1, 1, 1})).string());
  const std::string missing = (dir_ / "none.obj").string();
  RunResult run = Acdplan("decompose " + Quote(missing));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find(missing + ": cannot read the file: No such file or directory"),
            std::string::npos)
      << run.err;

  const fs::path garbage = Write("garbage.stl", "this is not a mesh\n");
  run = Acdplan("decompose " + Quote(garbage.string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find(garbage.string() + ": "), std::string::npos) << run.err;

  run = Acdplan("decompose " + box + " --measure sl");
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("--measure: applies to polygon files only"), std::string::npos) << run.err;
  for (const char* option : {"--min-convexity 0.5", "--hole-diameter pa", "--no-steiner",
                             "--geojson x.geojson", "--openings-geojson x.geojson"}) {
    ExpectUsageError(Acdplan("decompose " + box + " " + option));
  }
  const std::string polygon = Quote(kPolygons + "simple1.poly");
  for (const std::string option : {"--surface", "--max-hulls 4", "--obj x.obj", "--glb x.glb"}) {
    run = Acdplan("decompose " + polygon + " " + option);
    ExpectUsageError(run);
    EXPECT_NE(run.err.find("applies to mesh files only"), std::string::npos) << run.err;
  }

  ExpectUsageError(Acdplan("decompose " + box + " --tau -1"));
  ExpectUsageError(Acdplan("decompose " + box + " --tau-rel -0.5"));
  ExpectUsageError(Acdplan("decompose " + box + " --tau 1 --tau-rel 0.1"));
  ExpectUsageError(Acdplan("decompose " + box + " --max-hulls -1"));
  ExpectUsageError(Acdplan("decompose " + box + " --max-hulls 2.5"));
  for (const char* option : {"--json", "--obj", "--glb", "--svg"}) {
    run = Acdplan("decompose " + box + " " + option + " " + Quote(dir_.string()));
    ExpectUsageError(run);
    EXPECT_NE(run.err.find("is a directory"), std::string::npos) << run.err;
  }
  run = Acdplan("decompose " + box + " --obj " + Quote((dir_ / "parts.mtl").string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("cannot have it"), std::string::npos) << run.err;

  // An output under a regular file cannot be written: the error names it, exit status 2.
  const fs::path blocker = Write("blocker", "x");
  run = Acdplan("decompose " + box + " --svg " + Quote((blocker / "box.svg").string()));
  ExpectUsageError(run);
  EXPECT_NE(run.err.find((blocker / "box.svg").string()), std::string::npos) << run.err;

  // Nothing but the inputs was written.
  EXPECT_EQ(FileCount(), 3);
}

TEST_F(CliTest, RepairMakesMeshesSolidAndSaysWhat) {
  // Two cubes that cross each other: closed, but self-intersecting.
  const fs::path crossing = Write(
      "crossing.obj", BoxObj({0, 0, 0}, {1, 1, 1}) + BoxObj({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, 9));
  const RunResult strict = Acdplan("decompose " + Quote(crossing.string()));
  ExpectUsageError(strict);
  EXPECT_NE(strict.err.find(crossing.string() + ": not a solid: faces "), std::string::npos)
      << strict.err;
  EXPECT_NE(strict.err.find("intersect"), std::string::npos) << strict.err;

  const fs::path json_path = dir_ / "union.json";
  RunResult run = Acdplan("decompose " + Quote(crossing.string()) + " --repair --json " +
                          Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("  changed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solid ACD (closed, manifold, no self-intersections after --repair)"),
            std::string::npos)
      << run.out;
  // The union of the two cubes: 1 + 1 - 1/8.
  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_NEAR(j.at("stats").at("volume").get<double>(), 1.875, 1e-9);

  run = Acdplan("decompose " + Quote(crossing.string()) + " --surface");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("self-intersecting face pair"), std::string::npos) << run.out;

  // An open box: surface ACD as it is, solid ACD once --repair closes its hole.
  const fs::path open_box = Write("open_box.obj", BoxObj({0, 0, 0}, {1, 1, 1}, 1, true));
  run = Acdplan("decompose " + Quote(open_box.string()) + " --repair --json " +
                Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("after --repair"), std::string::npos) << run.out;
  EXPECT_NEAR(nlohmann::json::parse(Read(json_path)).at("stats").at("volume").get<double>(), 1.0,
              1e-9);
}

TEST_F(CliTest, WhatRepairCannotMendGetsTheSurfaceAcd) {
  // Two cubes that share an edge: closed, but that edge has 4 faces, which repair leaves alone.
  const fs::path cubes =
      Write("edge.obj", BoxObj({0, 0, 0}, {1, 1, 1}) + BoxObj({1, 1, 0}, {2, 2, 1}, 9));
  const RunResult strict = Acdplan("decompose " + Quote(cubes.string()));
  ExpectUsageError(strict);
  EXPECT_NE(strict.err.find(cubes.string() + ": not a solid: edge "), std::string::npos)
      << strict.err;
  const fs::path json_path = dir_ / "edge.json";
  const RunResult run = Acdplan("decompose " + Quote(cubes.string()) +
                                " --repair --tau-rel 0.2 --json " + Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("surface ACD (--repair could not make a solid: edge "), std::string::npos)
      << run.out;
  EXPECT_EQ(nlohmann::json::parse(Read(json_path)).at("stats").at("surface"), true);
}

TEST_F(CliTest, RepairUntanglesAShellThatCrossesItself) {
  // teddy.obj is closed but one of its shells crosses itself: --repair replaces it by the solid
  // it winds around.
  const std::string teddy = kMeshes + "teddy.obj";
  const RunResult strict = Acdplan("decompose " + Quote(teddy));
  ExpectUsageError(strict);
  EXPECT_NE(strict.err.find(teddy + ": not a solid: faces "), std::string::npos) << strict.err;
  const RunResult run = Acdplan("decompose " + Quote(teddy) + " --repair --tau-rel 0.2 --check");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("replaced 1 shell that crosses itself"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solid ACD (closed, manifold, no self-intersections after --repair)"),
            std::string::npos)
      << run.out;
}

TEST_F(CliTest, DecomposesACorpusMesh) {
  // cube-notch.obj, read as its v and f lines say (through assimp, its split normals made
  // every corner a vertex of its own, which preparation merged again).
  const fs::path json_path = dir_ / "cube-notch.json";
  const RunResult run = Acdplan("decompose " + Quote(kMeshes + "cube-notch.obj") +
                                " --tau-rel 0.02 --check --json " + Quote(json_path.string()));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("(56 vertices, 108 triangles)"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("duplicate vertices"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solid ACD"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(j.at("stats").at("surface"), false);
  EXPECT_GE(j.at("stats").at("hull_volume").get<double>(),
            j.at("stats").at("volume").get<double>() * (1 - 1e-9));
  EXPECT_LE(j.at("stats").at("max_concavity").get<double>(), j.at("tau").get<double>() * 1.000001);

  // A cap on the number of hulls.
  const RunResult capped =
      Acdplan("decompose " + Quote(kMeshes + "cube-notch.obj") +
              " --tau-rel 0.02 --max-hulls 2 --json " + Quote(json_path.string()));
  ASSERT_EQ(capped.status, 0) << capped.err;
  const nlohmann::json k = nlohmann::json::parse(Read(json_path));
  EXPECT_EQ(k.at("max_hulls"), 2);
  EXPECT_GE(k.at("components").size(), 1u);
  EXPECT_LE(k.at("components").size(), 2u);
  EXPECT_NEAR(k.at("stats").at("volume").get<double>(), j.at("stats").at("volume").get<double>(),
              1e-9 * j.at("stats").at("volume").get<double>());
}

TEST_F(CliTest, PlansACarScenarioAndRejectsGeometricOptions) {
  const std::string car = Quote(kSource + "configs/car_bug_trap.yaml");
  ExpectUsageError(Acdplan("plan " + car + " --sampler acd"));
  RunResult run = Acdplan("plan " + car + " --planner PRM");
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("unknown control planner 'PRM'"), std::string::npos) << run.err;
  run = Acdplan("plan " + Quote(kSource + "configs/bug_trap.yaml") + " --planner SyclopRRT");
  ExpectUsageError(run);
  EXPECT_NE(run.err.find("the control planners need a car scenario"), std::string::npos) << run.err;
  ExpectUsageError(Acdplan("plan " + car + " --samples 100"));
  // A short time budget: solved or not (exit 0 or 3) depends on the clock; the outputs do not.
  const fs::path json = dir_ / "car.json", svg = dir_ / "car.svg";
  run = Acdplan("plan " + car + " --planner SyclopEST --time 0.5 --json " + Quote(json.string()) +
                " --svg " + Quote(svg.string()));
  EXPECT_TRUE(run.status == 0 || run.status == 3) << run.status << run.err;
  EXPECT_NE(run.out.find("SyclopEST"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(Read(json));
  EXPECT_EQ(j["planner"], "SyclopEST");
  EXPECT_EQ(j["decomposition"], "acd");
  EXPECT_EQ(j["regions"], 8);
  EXPECT_NE(Read(svg).find("<g id=\"lead\">"), std::string::npos);
}

TEST_F(CliTest, PlansA2dOmplAppProblemFile) {
  const std::string cfg = kSource + "tests/data/ompl_app/planar.cfg";
  const RunResult run =
      Acdplan("plan " + Quote(cfg) + " --planner PRM --samples 300 --sampler acd --seed 1");
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("robot             polygon"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solved            yes"), std::string::npos) << run.out;
  // The file's ignored lines are warnings naming their line.
  EXPECT_NE(run.err.find("planar.cfg:21: longest_valid_segment_fraction"), std::string::npos)
      << run.err;

  const RunResult env = Acdplan("env " + Quote(cfg));
  EXPECT_EQ(env.status, 0) << env.err;
  EXPECT_NE(env.out.find("OMPL.app problem planar_fixture"), std::string::npos) << env.out;
  EXPECT_NE(env.out.find("obstacles        2 polygons"), std::string::npos) << env.out;

  // A 3D problem plans in SE(3); this fixture's start lies outside its bounds (the moved cube's
  // bounding box), which is bad input (exit 2).
  const RunResult spatial = Acdplan("plan " + Quote(kSource + "tests/data/ompl_app/spatial.cfg"));
  EXPECT_EQ(spatial.status, 2) << spatial.err;  // After the file's warnings.
  EXPECT_NE(spatial.err.find("spatial.cfg: start: the robot is in collision or out of bounds"),
            std::string::npos)
      << spatial.err;
  const RunResult car =
      Acdplan("plan " + Quote(Write("car.cfg", "[problem]\ncontrol=blimp\n").string()));
  ExpectUsageError(car);
  EXPECT_NE(car.err.find("car.cfg:2: control: 'blimp' is not supported (acdplan plans "
                         "kinematic_car and dynamic_car"),
            std::string::npos)
      << car.err;
}

TEST_F(CliTest, PlansAMovingAiProblemChosenWithProblem) {
  Write("maze.map", "type octile\nheight 4\nwidth 5\nmap\n@@@@@\n@.@.@\n@...@\n@@@@@\n");
  const std::string scen =
      Write("maze.map.scen", "version 1\n0\tmaps/maze.map\t5\t4\t1\t1\t3\t1\t3.41421356\n")
          .string();
  const RunResult none = Acdplan("plan " + Quote(scen));
  ExpectUsageError(none);
  EXPECT_NE(none.err.find(scen + ": a Moving AI scenario file holds many problems: choose one "
                                 "with --problem K (K from 0)"),
            std::string::npos)
      << none.err;
  const RunResult run = Acdplan("plan " + Quote(scen) + " --problem 0 --samples 300");
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("Moving AI problem 0 of " + scen +
                         " (bucket 0, optimal length on the grid 3.41421)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("solved            yes"), std::string::npos) << run.out;
  ExpectUsageError(Acdplan("plan " + Quote(scen) + " --problem 1"));
  ExpectUsageError(Acdplan("plan " + Quote(kSource + "configs/maze.yaml") + " --problem 0"));
  // env shows the world of a problem (its first by default: they share their map).
  const RunResult env = Acdplan("env " + Quote(scen));
  EXPECT_EQ(env.status, 0) << env.err;
  EXPECT_NE(env.out.find("(scenario; world " + (dir_ / "maze.map").string() + ")"),
            std::string::npos)
      << env.out;
  ExpectUsageError(Acdplan("env " + Quote(kSource + "configs/maze.yaml") + " --problem 0"));
}

TEST_F(CliTest, PlansA3dScenarioAndDrawsIt) {
  const fs::path svg = dir_ / "plan.svg", obj = dir_ / "plan.obj", glb = dir_ / "plan.glb";
  setenv("ACDPLAN_CACHE_DIR", (dir_ / "cache").c_str(), 1);  // Not the user's cache.
  const RunResult run = Acdplan("plan " + Quote(kSource + "configs/window_wall_3d.yaml") +
                                " --svg " + Quote(svg.string()) + " --obj " + Quote(obj.string()) +
                                " --glb " + Quote(glb.string()));
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("robot             mesh"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("2 components, 1 openings"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("solved            yes"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(svg) && fs::exists(obj) && fs::exists(glb));
  EXPECT_TRUE(fs::exists(dir_ / "plan.mtl"));
  // --obj and --glb are for 3D scenarios only.
  ExpectUsageError(
      Acdplan("plan " + Quote(kSource + "configs/demo.yaml") + " --obj " + Quote(obj.string())));
  EXPECT_TRUE(fs::exists(dir_ / "cache"));
  unsetenv("ACDPLAN_CACHE_DIR");
}

}  // namespace
