#include "tools/env_command.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "acd/concavity_measure.h"
#include "acd/decompose2d.h"
#include "acd/decomposition_io.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/obstacle_set.h"
#include "envs/free_space2d.h"
#include "envs/free_space_decomposition3d.h"
#include "envs/load_workspace.h"
#include "envs/robot.h"
#include "envs/world_svg.h"
#include "planning/scenario.h"
#include "planning/scenario_cfg.h"
#include "planning/scenario_moving_ai.h"
#include "planning/tau_diag.h"
#include "tools/report_lines.h"

namespace acdplan::tools {
namespace {

using Json = nlohmann::ordered_json;

// A scenario names its world under `workspace`; world files never have that key.
bool IsScenarioFile(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension != ".yaml" && extension != ".yml") return false;
  try {
    const YAML::Node root = YAML::LoadFile(path);
    return root.IsMap() && root["workspace"];
  } catch (const YAML::Exception&) {
    return false;  // The world loader reports the syntax error with its line.
  }
}

std::string Milliseconds(double ms) { return FormatSignificant(ms, 3) + " ms"; }

void WriteOutput(const std::string& path, const std::string& text) {
  try {
    WriteFileAtomically(path, text);
  } catch (const std::runtime_error& error) {
    throw acdplan::InputError(error.what());  // The user's path to fix: exit status 2.
  }
}

// The report's "name  value" lines.
constexpr ReportLines Line(16);

// The report's first fields, common to 2D and 3D worlds: bounds as [min..., max...].
Json ReportHeader(const EnvArguments& args, const std::string& kind, const std::string& description,
                  const Eigen::VectorXd& min, const Eigen::VectorXd& max) {
  Json j;
  j["format"] = "acdplan.env/1";
  j["input"] = args.input;
  j["kind"] = kind;
  j["dimension"] = min.size();
  j["description"] = description;
  Json box = Json::array();
  for (Eigen::Index i = 0; i < min.size(); ++i) box.push_back(min[i]);
  for (Eigen::Index i = 0; i < max.size(); ++i) box.push_back(max[i]);
  j["bounds"] = std::move(box);
  return j;
}

// The tau of the free space's ACD, as a fraction of the bounds' diagonal: the option, else the
// scenario's, else the default.
double TauDiag(const EnvArguments& args, const planning::Scenario* scenario) {
  return args.tau_diag >= 0 ? args.tau_diag
         : scenario         ? scenario->tau_diag
                            : planning::kDefaultTauDiag;
}

// The robot and planner lines of a scenario's report.
void ScenarioLines(const planning::Scenario& scenario) {
  const envs::Robot& robot = scenario.robot;
  std::string text = ToString(robot.shape);
  if (robot.shape == envs::RobotShape::kDisc) text += ", radius " + ReportNumber(robot.radius);
  if (robot.shape == envs::RobotShape::kPolygon) {
    text += ", " + std::to_string(robot.polygon.outer.size()) + " vertices, bounding radius " +
            ReportNumber(robot.BoundingRadius());
  }
  if (robot.shape == envs::RobotShape::kMesh) {
    text += ", " + Plural(robot.mesh.triangles.rows(), "triangle") + ", bounding radius " +
            ReportNumber(robot.BoundingRadius());
  }
  Line("robot", text);
  Line("planner", planning::ToString(scenario.planner) + " with the " +
                      planning::ToString(scenario.sampler) + " sampler");
}

int Report2d(const EnvArguments& args, const std::string& kind, const envs::Workspace2d& workspace,
             const planning::Scenario* scenario) {
  const double tau_diag = TauDiag(args, scenario);
  const acd::ConcavityMeasure measure = !args.measure.empty()
                                            ? acd::ParseConcavityMeasure(args.measure)
                                        : scenario ? scenario->measure
                                                   : acd::ConcavityMeasure::kShortestPath;
  const double diagonal = workspace.bounds.sizes().norm();

  Stopwatch stopwatch;
  const std::vector<acd::Polygon2d> free_space = envs::FreeSpace2d(workspace);
  const double free_space_ms = stopwatch.Milliseconds();
  stopwatch.Restart();
  acd::Decompose2dOptions options;
  options.tau = planning::TauOfBounds(tau_diag, workspace.bounds);
  options.measure = measure;
  const acd::Decomposition2d decomposition = acd::Decompose2d(free_space, options);
  const double decomposition_ms = stopwatch.Milliseconds();
  const collision::ObstacleSet obstacles = collision::BuildObstacleSet(workspace);

  int obstacle_vertices = 0, obstacle_holes = 0;
  for (const acd::Polygon2d& o : workspace.obstacles) {
    obstacle_vertices += acd::VertexCount(o);
    obstacle_holes += static_cast<int>(o.holes.size());
  }
  double free_area = 0.0;
  int free_holes = 0;
  for (const acd::Polygon2d& region : free_space) {
    free_area += acd::Area(region);
    free_holes += static_cast<int>(region.holes.size());
  }
  const double bounds_area = workspace.bounds.volume();
  double narrowest = INFINITY;
  for (const acd::Opening2d& o : decomposition.openings) {
    narrowest = std::min(narrowest, (o.b - o.a).norm());
  }

  const Eigen::Vector2d lo = workspace.bounds.min(), hi = workspace.bounds.max();
  Line("world", args.input + " (" + kind + ")");
  if (!workspace.description.empty()) Line("description", workspace.description);
  Line("bounds", "[" + ReportNumber(lo.x()) + ", " + ReportNumber(lo.y()) + "] to [" +
                     ReportNumber(hi.x()) + ", " + ReportNumber(hi.y()) + "]");
  Line("obstacles", Plural(workspace.obstacles.size(), "polygon") + ", " +
                        std::to_string(obstacle_vertices) + " vertices, " +
                        Plural(obstacle_holes, "hole"));
  Line("free space", Plural(free_space.size(), "region") + ", " + Plural(free_holes, "hole") +
                         ", " + ReportNumber(100.0 * free_area / bounds_area) +
                         "% of the bounds (" + Milliseconds(free_space_ms) + ")");
  Line("decomposition", "tau " + ReportNumber(options.tau) + " (tau_diag " +
                            ReportNumber(tau_diag) + " x bounds diagonal " +
                            ReportNumber(diagonal) + "), measure " + acd::ToString(measure) + ": " +
                            std::to_string(decomposition.components.size()) + " components, " +
                            std::to_string(decomposition.openings.size()) + " openings (" +
                            Milliseconds(decomposition_ms) + ")");
  if (!decomposition.openings.empty()) Line("narrowest gap", ReportNumber(narrowest));
  Line("obstacle hulls",
       std::to_string(obstacles.pieces.size()) + " from " + obstacles.hulls_source);
  if (scenario) ScenarioLines(*scenario);

  if (!args.svg_path.empty()) {
    const std::string caption =
        args.input + ": " + std::to_string(decomposition.components.size()) + " components, " +
        std::to_string(decomposition.openings.size()) + " openings (orange), tau_diag " +
        ReportNumber(tau_diag) + ", " + acd::ToString(measure);
    WriteOutput(args.svg_path, envs::WorldToSvg(workspace, decomposition, caption));
    Line("wrote", args.svg_path);
  }
  if (!args.json_path.empty()) {
    Json j = ReportHeader(args, kind, workspace.description, lo, hi);
    j["obstacles"] = workspace.obstacles.size();
    j["obstacle_vertices"] = obstacle_vertices;
    j["free_regions"] = free_space.size();
    j["free_area"] = free_area;
    j["tau"] = options.tau;
    j["tau_diag"] = tau_diag;
    j["measure"] = acd::ToString(measure);
    j["components"] = decomposition.components.size();
    j["openings"] = decomposition.openings.size();
    j["narrowest_opening"] = decomposition.openings.empty() ? Json(nullptr) : Json(narrowest);
    j["obstacle_hulls"] = obstacles.pieces.size();
    j["hulls_source"] = obstacles.hulls_source;
    if (scenario) j["robot"] = ToString(scenario->robot.shape);
    WriteOutput(args.json_path, j.dump(2) + "\n");
    Line("wrote", args.json_path);
  }
  return 0;
}

int Report3d(const EnvArguments& args, const std::string& kind, const envs::Workspace3d& workspace,
             const planning::Scenario* scenario) {
  if (!args.svg_path.empty()) {
    throw acdplan::InputError("--svg " + args.svg_path + ": " + args.input +
                              " is a 3D world; pictures are drawn for 2D worlds only");
  }
  // The free space's ACD as the planner builds it (and from the same disk cache).
  const double tau_diag = TauDiag(args, scenario);
  const double diagonal = workspace.bounds.sizes().norm();
  envs::FreeSpaceDecomposition3dOptions options;
  options.tau = planning::TauOfBounds(tau_diag, workspace.bounds);
  const envs::FreeSpaceDecomposition3d free = envs::DecomposeFreeSpace3d(workspace, options);
  double narrowest = INFINITY;
  for (const envs::FreeOpening3d& o : free.openings) narrowest = std::min(narrowest, o.width);

  const collision::ObstacleSet obstacles = collision::BuildObstacleSet(workspace);
  long vertices = 0;
  for (const acd::TriangleMesh& mesh : workspace.obstacles) vertices += mesh.vertices.rows();
  int open_components = 0, open_pieces = 0, convex_pieces = 0;
  for (const collision::ObstacleComponent& c : obstacles.components) open_components += !c.closed;
  for (const collision::ObstaclePiece& piece : obstacles.pieces) {
    open_pieces += !piece.closed;
    convex_pieces += piece.convex;
  }

  const Eigen::Vector3d lo = workspace.bounds.min(), hi = workspace.bounds.max();
  Line("world", args.input + " (" + kind + ")");
  if (!workspace.description.empty()) Line("description", workspace.description);
  Line("bounds", "[" + ReportNumber(lo.x()) + ", " + ReportNumber(lo.y()) + ", " +
                     ReportNumber(lo.z()) + "] to [" + ReportNumber(hi.x()) + ", " +
                     ReportNumber(hi.y()) + ", " + ReportNumber(hi.z()) + "]");
  Line("obstacles", Plural(workspace.obstacles.size(), "mesh") + ", " +
                        std::to_string(collision::TriangleCount(obstacles)) + " triangles, " +
                        std::to_string(vertices) + " vertices");
  Line("obstacle hulls", std::to_string(obstacles.pieces.size()) + " from " +
                             obstacles.hulls_source + "; " + std::to_string(convex_pieces) +
                             " convex (their own hulls)");
  Line("obstacle parts", Plural(obstacles.components.size(), "part") + ", " +
                             std::to_string(open_components) +
                             " open (no exact point location inside those)");
  Line("free space",
       ReportNumber(100.0 * free.free_volume / workspace.bounds.volume()) + "% of the bounds");
  Line("decomposition", "tau " + ReportNumber(options.tau) + " (tau_diag " +
                            ReportNumber(tau_diag) + " x bounds diagonal " +
                            ReportNumber(diagonal) +
                            "), solid ACD: " + Plural(free.components.size(), "component") + ", " +
                            Plural(free.openings.size(), "opening") + " (" +
                            (free.from_cache ? "from the cache; computed in " : "") +
                            Milliseconds(free.compute_ms) + ")");
  if (!free.openings.empty()) Line("narrowest gap", ReportNumber(narrowest));
  for (const std::string& note : free.notes) Line("note", note);
  if (scenario) ScenarioLines(*scenario);
  for (const std::string& note : obstacles.notes) Line("note", note);
  if (!args.json_path.empty()) {
    Json j = ReportHeader(args, kind, workspace.description, lo, hi);
    j["free_volume"] = free.free_volume;
    j["tau"] = options.tau;
    j["tau_diag"] = tau_diag;
    j["components"] = free.components.size();
    j["openings"] = free.openings.size();
    j["narrowest_opening"] = free.openings.empty() ? Json(nullptr) : Json(narrowest);
    j["free_space_notes"] = free.notes;
    if (scenario) j["robot"] = ToString(scenario->robot.shape);
    j["obstacles"] = workspace.obstacles.size();
    j["triangles"] = collision::TriangleCount(obstacles);
    j["obstacle_hulls"] = obstacles.pieces.size();
    j["open_pieces"] = open_pieces;
    j["convex_hulls"] = convex_pieces;
    j["obstacle_components"] = obstacles.components.size();
    j["open_components"] = open_components;
    j["hulls_source"] = obstacles.hulls_source;
    j["notes"] = obstacles.notes;
    WriteOutput(args.json_path, j.dump(2) + "\n");
    Line("wrote", args.json_path);
  }
  return 0;
}

// A CLI11 check from a name parser (ParseConcavityMeasure() and the like): "" for a name it
// knows, else its InputError's message.
template <typename Parse>
auto NameCheck(Parse parse) {
  return [parse](const std::string& name) {
    try {
      parse(name);
      return std::string();
    } catch (const acdplan::InputError& error) {
      return std::string(error.what());
    }
  };
}

}  // namespace

CLI::App* AddEnvCommand(CLI::App* app, EnvArguments* args) {
  CLI::App* env = app->add_subcommand(
      "env",
      "Load a world (workspace YAML 2D or 3D, occupancy map.yaml, Moving AI .map, .poly/.wkt/"
      ".geojson/.shp/.gpkg/.kml/.kmz obstacles, a mesh) or a scenario's world, report what was "
      "loaded, "
      "its "
      "free "
      "space and ACD; --svg draws a 2D world and its decomposition. Exit status: 0 ok, 2 bad "
      "input or usage, 1 internal error.");
  env->add_option("FILE", args->input, "World file or scenario YAML")->required();
  CLI::Option* tau_diag =
      env->add_option("--tau-diag", args->tau_diag,
                      "ACD tau as a fraction of the bounds' diagonal (default: the scenario's, "
                      "else 0.02)")
          ->check(CLI::NonNegativeNumber);
  // The older spelling, kept working: tau_rel means the reference radius in `decompose`.
  CLI::Option* tau_rel =
      env->add_option("--tau-rel", args->tau_rel, "Older spelling of --tau-diag (prints a warning)")
          ->check(CLI::NonNegativeNumber);
  tau_diag->excludes(tau_rel);
  tau_rel->excludes(tau_diag);
  env->add_option("--measure", args->measure, "Concavity measure: sl, sp, h1 or h2")
      ->check(NameCheck(acd::ParseConcavityMeasure));
  env->add_flag("--repair", args->repair,
                "Make invalid obstacle polygons valid (even-odd rule) instead of rejecting them; "
                "each change is printed on stderr (a scenario file says `repair: true`)");
  env->add_option("--unknown", args->unknown,
                  "Occupancy maps: cells neither occupied nor free are blocked (default) or free")
      ->check(NameCheck(envs::ParseUnknownCells));
  env->add_option("--problem", args->problem,
                  "With a Moving AI .scen file: show its problem K (default 0: a benchmark's "
                  "problems share one map)")
      ->check(CLI::NonNegativeNumber);
  env->add_option("--svg", args->svg_path, "Write a picture of the 2D world and its ACD here");
  env->add_option("--json", args->json_path, "Write the report as JSON here");
  return env;
}

int RunEnv(const EnvArguments& given) {
  EnvArguments args = given;
  if (args.tau_rel >= 0) {
    std::fprintf(stderr,
                 "acdplan: warning: --tau-rel is read as --tau-diag, a fraction of the bounds' "
                 "diagonal; write --tau-diag (decompose's --tau-rel is relative to the reference "
                 "radius)\n");
    args.tau_diag = args.tau_rel;
  }
  const bool moving_ai = planning::IsMovingAiScenarioFile(args.input);
  if (!moving_ai && args.problem >= 0) {
    throw InputError("--problem: only for a Moving AI .scen file (" + args.input + " is not one)");
  }
  if (IsScenarioFile(args.input) || planning::IsOmplAppProblemFile(args.input) || moving_ai) {
    const planning::Scenario scenario = planning::LoadScenarioFile(
        args.input, moving_ai ? std::max(args.problem, 0) : args.problem);
    for (const std::string& warning : scenario.warnings) {
      std::fprintf(stderr, "acdplan: warning: %s\n", warning.c_str());
    }
    if (args.repair) {
      std::fprintf(stderr,
                   "acdplan: warning: --repair does not apply to a scenario file; its `repair: "
                   "true` key does\n");
    }
    if (!args.unknown.empty()) {
      std::fprintf(stderr,
                   "acdplan: warning: --unknown does not apply to a scenario file; its `unknown: "
                   "free` key does\n");
    }
    const std::string kind = "scenario; world " + scenario.workspace_label;
    if (scenario.dimension == 3) return Report3d(args, kind, scenario.workspace3d, &scenario);
    return Report2d(args, kind, scenario.workspace, &scenario);
  }
  std::vector<std::string> notes;
  acd::ReadPolygonsOptions polygons;
  polygons.repair = args.repair;
  polygons.notes = &notes;
  envs::OccupancyMapOptions map;
  map.notes = &notes;
  if (!args.unknown.empty()) map.unknown = envs::ParseUnknownCells(args.unknown);
  const envs::World world = envs::LoadWorld(args.input, polygons, map);
  for (const std::string& note : notes) std::fprintf(stderr, "acdplan: %s\n", note.c_str());
  if (!args.unknown.empty() && world.kind != "occupancy map") {
    std::fprintf(stderr,
                 "acdplan: warning: --unknown applies to occupancy maps only (%s is a %s)\n",
                 args.input.c_str(), world.kind.c_str());
  }
  if (world.dimension == 3) return Report3d(args, world.kind, world.workspace3d, nullptr);
  return Report2d(args, world.kind, world.workspace2d, nullptr);
}

}  // namespace acdplan::tools
