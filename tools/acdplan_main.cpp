// The acdplan command line. Exit statuses (DESIGN.md): 0 success; 2 bad input or usage, with
// one line "acdplan: error: <message>" on stderr; 1 internal error.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/concavity_measure.h"
#include "acd/decompose2d.h"
#include "acd/decomposition2d.h"
#include "acd/decomposition3d_io.h"
#include "acd/decomposition_io.h"
#include "acd/polygon2d.h"
#include "acd/read_polygons.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "bench/collision_bench.h"
#include "bench/merge.h"
#include "bench/outputs.h"
#include "bench/record.h"
#include "bench/runner.h"
#include "bench/spec.h"
#include "bench/targets.h"
#include "envs/mesh_loader.h"
#include "planning/plan_picture3d.h"
#include "planning/plan_scenario.h"
#include "planning/scenario.h"
#include "planning/scenario_cfg.h"
#include "planning/scenario_moving_ai.h"
#include "tools/check_report.h"
#include "tools/decompose3d_command.h"
#include "tools/env_command.h"
#include "tools/plot_bench.h"

namespace {

namespace acd = acdplan::acd;

/// What `acdplan decompose` was asked to do.
struct DecomposeArguments {
  std::string input;
  double tau = 0.0;
  double tau_rel = -1.0;  ///< < 0: not given.
  std::string measure = "sp";
  double min_convexity = 0.0;
  std::string hole_diameter = "auto";
  bool no_steiner = false;
  std::string json_path;
  std::string svg_path;
  std::string geojson_path;           ///< Polygons only.
  std::string openings_geojson_path;  ///< Polygons only.
  bool check = false;
  bool repair = false;
  // Meshes only.
  bool surface = false;
  int max_hulls = 0;
  double merge_growth = 0.0;  ///< Read only if given (InputKindOptions::merge_growth).
  std::string obj_path, glb_path;
};

/// Options that apply to one kind of INPUT only: given with the other kind, a usage error.
struct InputKindOptions {
  std::vector<CLI::Option*> polygons_only, meshes_only;
  CLI::Option* tau = nullptr;
  CLI::Option* merge_growth = nullptr;
};

/// `acdplan decompose MESH` (tools/decompose3d_command.h).
int RunDecomposeMesh(const DecomposeArguments& args, const InputKindOptions& kinds) {
  for (const CLI::Option* option : kinds.polygons_only) {
    if (option->count() > 0) {
      throw acdplan::InputError(option->get_name() + ": applies to polygon files only (" +
                                args.input + " is a mesh)");
    }
  }
  acdplan::tools::Decompose3dArguments mesh_args;
  mesh_args.input = args.input;
  if (kinds.tau->count() > 0) mesh_args.tau = args.tau;
  mesh_args.tau_rel = args.tau_rel;
  mesh_args.surface = args.surface;
  mesh_args.max_hulls = args.max_hulls;
  if (kinds.merge_growth->count() > 0) mesh_args.merge_growth = args.merge_growth;
  mesh_args.repair = args.repair;
  mesh_args.check = args.check;
  mesh_args.json_path = args.json_path;
  mesh_args.obj_path = args.obj_path;
  mesh_args.glb_path = args.glb_path;
  mesh_args.svg_path = args.svg_path;
  return acdplan::tools::RunDecompose3d(mesh_args);
}

/// A CLI11 check from a parser that throws acdplan::InputError, so the value is checked while
/// parsing and the message names the option ("--measure: unknown concavity measure 'x' ...").
template <typename Parse>
CLI::Validator ParsedBy(Parse parse) {
  return CLI::Validator(
      [parse](std::string& value) -> std::string {
        try {
          parse(value);
        } catch (const acdplan::InputError& error) {
          return error.what();
        }
        return "";
      },
      "");
}

/// A check on a number: `accept(x)` or the message "must be <rule>, got <value>".
template <typename Accept>
CLI::Validator NumberThat(Accept accept, const std::string& rule) {
  return CLI::Validator(
      [accept, rule](std::string& value) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(value, x) || !accept(x)) {
          return "must be " + rule + ", got " + value;
        }
        return "";
      },
      "");
}

using acdplan::CheckOutputPath;

int RunDecompose(const DecomposeArguments& args, const InputKindOptions& kinds) {
  if (acdplan::envs::IsMeshFile(args.input)) return RunDecomposeMesh(args, kinds);
  if (!acd::IsPolygonFile(args.input)) {
    throw acdplan::InputError(args.input + ": unknown file extension '" +
                              std::filesystem::path(args.input).extension().string() +
                              "' (expected a polygon file, " + acd::kPolygonFileExtensions +
                              ", or a mesh, " + acdplan::envs::kMeshFileExtensions + ")");
  }
  for (const CLI::Option* option : kinds.meshes_only) {
    if (option->count() > 0) {
      throw acdplan::InputError(option->get_name() + ": applies to mesh files only (" + args.input +
                                " is a polygon file)");
    }
  }
  // Everything the user typed is checked before the (possibly long) decomposition.
  acd::Decompose2dOptions options;
  options.measure = acd::ParseConcavityMeasure(args.measure);
  options.hole_diameter = acd::ParseHoleDiameter(args.hole_diameter);
  options.min_convexity = args.min_convexity;
  options.steiner_cuts = !args.no_steiner;
  CheckOutputPath("--json", args.json_path);
  CheckOutputPath("--svg", args.svg_path);
  CheckOutputPath("--geojson", args.geojson_path);
  CheckOutputPath("--openings-geojson", args.openings_geojson_path);

  std::vector<double> radii;       // As written in the file: the dissertation's tables use these.
  std::vector<std::string> notes;  // Reader warnings and repair changes, one line each.
  acd::ReadPolygonsOptions read_options;
  read_options.repair = args.repair;
  read_options.notes = &notes;
  read_options.disjoint_members = true;  // A MULTIPOLYGON is one region to decompose.
  read_options.skip_non_areal = true;    // Points and lines in a layer have nothing to decompose.
  std::vector<int> sources;              // Per polygon: the file's polygon it comes from.
  std::vector<int> features;             // Per polygon: the file's feature it comes from.
  read_options.sources = &sources;
  read_options.features = &features;
  std::vector<std::string> properties;  // Per feature: its attributes, for the GeoJSON only.
  if (!args.geojson_path.empty()) read_options.feature_properties = &properties;
  const std::vector<acd::Polygon2d> polygons = acd::ReadPolygons(args.input, &radii, read_options);
  for (const std::string& note : notes) std::cerr << "acdplan: " << note << "\n";
  int vertices = 0;
  for (const acd::Polygon2d& polygon : polygons) vertices += acd::VertexCount(polygon);
  const double radius = *std::max_element(radii.begin(), radii.end());
  // One tau for the whole file: relative to the largest polygon, so a small island next to a
  // large one is not cut finer than the large one.
  options.tau = args.tau_rel >= 0 ? args.tau_rel * radius : args.tau;

  const acd::Decomposition2d decomposition = acd::Decompose2d(polygons, options);

  if (args.check) {
    const acd::DecompositionCheck check = acd::CheckDecomposition(polygons, decomposition);
    if (!check.ok()) return acdplan::tools::ReportFailedCheck(args.input, check);
  }

  // Outputs are produced in memory first and each written atomically, so a failure leaves
  // no partial file behind.
  acd::DecompositionLabels labels;
  labels.input = args.input;
  labels.tau_rel = args.tau_rel;
  std::vector<std::string> written;
  try {
    if (!args.json_path.empty()) {
      acdplan::WriteFileAtomically(
          args.json_path, acd::DecompositionToJson(decomposition, labels, sources, features));
      written.push_back(args.json_path);
    }
    if (!args.geojson_path.empty()) {
      acdplan::WriteFileAtomically(
          args.geojson_path,
          acd::DecompositionToGeoJson(decomposition, labels, sources, features, properties));
      written.push_back(args.geojson_path);
    }
    if (!args.openings_geojson_path.empty()) {
      acdplan::WriteFileAtomically(args.openings_geojson_path,
                                   acd::OpeningsToGeoJson(decomposition, labels));
      written.push_back(args.openings_geojson_path);
    }
    if (!args.svg_path.empty()) {
      acdplan::WriteFileAtomically(args.svg_path, acd::DecompositionToSvg(decomposition, labels));
      written.push_back(args.svg_path);
    }
  } catch (const std::runtime_error& error) {
    // An unwritable output path is the user's to fix, not a bug: exit status 2.
    throw acdplan::InputError(error.what());
  }

  const acd::DecompositionStats2d& stats = decomposition.stats;
  std::printf("input          %s (%s, %s)\n", args.input.c_str(),
              acdplan::Plural(polygons.size(), "polygon").c_str(),
              acdplan::Plural(vertices, "vertex").c_str());
  std::printf("notches        %d\n", stats.notches);
  if (args.tau_rel >= 0) {
    std::printf("tau            %.6g (tau_rel %.6g x radius %.6g)\n", decomposition.tau,
                args.tau_rel, radius);
  } else {
    std::printf("tau            %.6g\n", decomposition.tau);
  }
  if (decomposition.min_convexity > 0) {
    std::printf("min convexity  %.6g\n", decomposition.min_convexity);
  }
  std::printf("measure        %s\n", acd::ToString(decomposition.measure).c_str());
  std::printf("components     %d\n", stats.components);
  std::printf("max concavity  %.6g\n", stats.max_concavity);
  std::printf("convexity      %.6g\n", stats.convexity);
  std::printf("time           %.3f ms\n", stats.time_ms);
  if (args.check) std::printf("check          ok\n");
  for (const std::string& path : written) std::printf("wrote          %s\n", path.c_str());
  return 0;
}

/// bench-collision's default --mesh-dir, relative to the working directory (the repository).
const char* const kDefaultMeshDir = "data/meshes/vhacd";

/// `acdplan bench-collision`: bench/collision_bench.h, a Markdown table on stdout.
int RunBenchCollision(acdplan::bench::BenchCollisionOptions options, const std::string& json_path,
                      const std::string& targets_path) {
  namespace bench = acdplan::bench;
  std::error_code ec;
  if (!options.mesh_dir.empty() && !std::filesystem::is_directory(options.mesh_dir, ec)) {
    throw acdplan::InputError(
        "--mesh-dir " + options.mesh_dir +
        ": not a folder (the default is relative to the working directory: run "
        "from the repository, or give --mesh-dir DIR, or --mesh-dir '' to skip "
        "3D)");
  }
  std::vector<bench::Target> targets;
  if (!targets_path.empty()) {
    targets = bench::LoadTargetsFile(targets_path, bench::CollisionTargetVocabulary());
  }
  const auto rows = bench::BenchCollision(options, &std::cerr);
  std::cout << bench::BenchCollisionMarkdown(rows, targets);
  if (!json_path.empty()) {
    acdplan::WriteFileAtomically(json_path, bench::BenchCollisionJson(rows, options));
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

/// What `acdplan plan` was asked to do (each override < 0 or empty: keep the scenario's).
struct PlanArguments {
  std::string scenario;
  int problem = -1;  ///< Of a Moving AI .scen file.
  std::string sampler, planner;
  long long seed = -1;
  double time = -1;
  int samples = -1;
  std::string json_path, svg_path;
  std::string obj_path, glb_path;  ///< 3D scenarios: the scene (world, openings, path).
};

/// `acdplan plan`: exit 0 solved, 3 not solved within the budget, 2 bad input.
int RunPlan(const PlanArguments& args) {
  namespace planning = acdplan::planning;
  if (planning::IsMovingAiScenarioFile(args.scenario) && args.problem < 0) {
    throw acdplan::InputError(args.scenario +
                              ": a Moving AI scenario file holds many problems: "
                              "choose one with --problem K (K from 0)");
  }
  planning::Scenario scenario = planning::LoadScenarioFile(args.scenario, args.problem);
  for (const std::string& warning : scenario.warnings) {
    std::fprintf(stderr, "acdplan: warning: %s\n", warning.c_str());
  }
  if (scenario.car) {
    // A car: a control planner, and no sampler (Syclop follows its decomposition).
    if (!args.sampler.empty()) {
      throw acdplan::InputError("--sampler: " + args.scenario +
                                " plans a car with a control planner, which takes no sampler");
    }
    if (!args.planner.empty()) {
      try {
        scenario.car->planner = planning::control::ParseControlPlanner(args.planner);
      } catch (const acdplan::InputError& error) {
        throw acdplan::InputError("--planner: " + args.scenario + " plans a car: " + error.what());
      }
    }
  } else {
    if (!args.sampler.empty()) scenario.sampler = planning::ParseSamplerType(args.sampler);
    if (!args.planner.empty()) {
      try {
        scenario.planner = planning::ParsePlannerType(args.planner);
      } catch (const acdplan::InputError& error) {
        throw acdplan::InputError("--planner: " + std::string(error.what()) +
                                  "; the control planners need a car scenario");
      }
    }
  }
  if (args.seed >= 0) scenario.seed = static_cast<std::uint64_t>(args.seed);
  if (args.time > 0) scenario.time_limit = args.time, scenario.samples = 0;
  if (args.samples > 0) scenario.samples = args.samples;
  planning::CheckScenario(scenario);
  CheckOutputPath("--json", args.json_path);
  CheckOutputPath("--svg", args.svg_path);
  CheckOutputPath("--obj", args.obj_path);
  CheckOutputPath("--glb", args.glb_path);
  if (scenario.dimension != 3 && !(args.obj_path.empty() && args.glb_path.empty())) {
    throw acdplan::InputError("--obj / --glb: only for a 3D scenario (" + args.scenario +
                              " is 2D; use --svg)");
  }
  planning::ConfigureOmpl(scenario.seed, true);

  const planning::PlanResult result = planning::PlanScenario(scenario);
  for (const std::string& note : result.notes) {
    std::fprintf(stderr, "acdplan: note: %s\n", note.c_str());
  }
  try {
    if (!args.json_path.empty()) {
      acdplan::WriteFileAtomically(args.json_path, planning::PlanResultToJson(scenario, result));
    }
    if (!args.svg_path.empty()) {
      acdplan::WriteFileAtomically(args.svg_path, planning::PlanResultToSvg(scenario, result));
    }
    if (!args.obj_path.empty() || !args.glb_path.empty()) {
      const auto scene = planning::PlanScene3d(scenario, result);
      if (!args.obj_path.empty()) {
        const std::string mtl =
            std::filesystem::path(args.obj_path).replace_extension(".mtl").string();
        const acdplan::acd::ObjFiles files =
            acdplan::acd::SceneToObj(scene, std::filesystem::path(mtl).filename().string(),
                                     "acdplan plan: " + args.scenario);
        acdplan::WriteFileAtomically(mtl, files.mtl);
        acdplan::WriteFileAtomically(args.obj_path, files.obj);
      }
      if (!args.glb_path.empty()) {
        const std::vector<std::uint8_t> glb = acdplan::acd::SceneToGlb(scene);
        acdplan::WriteFileAtomically(args.glb_path, std::string(glb.begin(), glb.end()));
      }
    }
  } catch (const std::runtime_error& error) {
    throw acdplan::InputError(error.what());
  }
  std::printf("scenario          %s\n", args.scenario.c_str());
  if (!scenario.description.empty())
    std::printf("description       %s\n", scenario.description.c_str());
  std::printf("workspace         %s\n", scenario.workspace_label.c_str());
  if (result.car) {
    const planning::CarPlan& car = *result.car;
    std::printf("robot             %s (body: %s)\n",
                planning::control::ToString(scenario.car->model).c_str(),
                acdplan::envs::ToString(scenario.robot.shape).c_str());
    std::printf("planner           %s (%s, seed %llu)\n",
                planning::control::ToString(car.planner).c_str(), result.budget.c_str(),
                static_cast<unsigned long long>(scenario.seed));
    if (car.decomposition) {
      std::printf("decomposition     %s, %d regions, %zu passed through\n",
                  planning::control::ToString(*car.decomposition).c_str(), car.regions,
                  car.visited_regions.size());
    }
    std::printf("tree states       %llu\n", static_cast<unsigned long long>(result.samples));
  } else {
    std::printf("robot             %s\n", acdplan::envs::ToString(scenario.robot.shape).c_str());
    std::printf("sampler           %s\n", planning::ToString(result.sampler).c_str());
    std::printf("planner           %s (%s, seed %llu)\n",
                planning::ToString(result.planner).c_str(), result.budget.c_str(),
                static_cast<unsigned long long>(scenario.seed));
    std::printf("acd               %d components, %d openings, %.3f ms\n", result.components,
                result.openings, result.decomposition_ms);
    std::printf("samples           %llu\n", static_cast<unsigned long long>(result.samples));
  }
  std::printf("collision checks  %llu\n", static_cast<unsigned long long>(result.collision_checks));
  std::printf("solved            %s\n", result.solved ? "yes" : "no");
  if (result.solved && result.car) {
    std::printf("trajectory        %zu controls, duration %.6g s\n",
                result.path.empty() ? 0 : result.path.size() - 1, result.car->duration_s);
  } else if (result.solved) {
    std::printf("path              %zu states, length %.6g\n", result.path.size(),
                result.path_length);
  }
  std::printf("time              %.3f s\n", result.time_s);
  if (!args.json_path.empty()) std::printf("wrote             %s\n", args.json_path.c_str());
  if (!args.svg_path.empty()) std::printf("wrote             %s\n", args.svg_path.c_str());
  return result.solved ? 0 : 3;
}

/// What `acdplan bench` / `bench-merge` were asked to do.
struct BenchArguments {
  std::string spec;
  int runs = 0;  ///< 0: the spec's.
  std::string out;
  std::string shard = "1/1";
  int jobs = 1;
  bool no_plots = false;
  std::vector<std::string> merge_dirs;
};

volatile std::sig_atomic_t g_bench_stop = 0;

extern "C" void OnBenchInterrupt(int) { g_bench_stop = 1; }

/// The output folder must be a folder (or not exist yet).
void CheckOutputDir(const std::string& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw acdplan::InputError("--out " + dir + ": exists and is not a folder");
  }
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M:%S", &tm);
  return buffer;
}

void ListOutputs(const std::string& dir) {
  std::printf("wrote %s/{runs.csv,bench.json,results.json,summary.md,ompl_*.log", dir.c_str());
  std::error_code ec;
  if (std::filesystem::exists(std::filesystem::path(dir) / "success_vs_width.png", ec)) {
    std::printf(",*.png");
  }
  std::printf("}\n");
}

/// `acdplan bench`: exit 0 when the runs are done (whatever they found), 130 after Ctrl-C
/// (the outputs then hold the finished runs), 2 bad input.
int RunBench(const BenchArguments& args) {
  namespace bench = acdplan::bench;
  const bench::BenchSpec spec = bench::LoadBenchSpec(args.spec);
  // The file's warnings, then its worlds' (once each: a sweep's worlds share their file's).
  std::vector<std::string> warnings = spec.warnings;
  for (const bench::BenchWorld& world : spec.worlds) {
    for (const std::string& warning : world.scenario.warnings) {
      if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end()) {
        warnings.push_back(warning);
      }
    }
  }
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "acdplan: warning: %s\n", warning.c_str());
  }
  const bench::BenchShard shard = bench::ParseBenchShard(args.shard);
  const std::string out = args.out.empty() ? "bench-out/" + spec.name : args.out;
  CheckOutputDir(out);

  bench::BenchManifest manifest;
  manifest.name = spec.name;
  manifest.description = spec.description;
  manifest.spec = args.spec;
  manifest.seed = spec.seed;
  manifest.runs = args.runs > 0 ? args.runs : spec.runs;
  manifest.cases = static_cast<int>(spec.cases.size());
  manifest.shards = {args.shard};
  manifest.planned_runs = bench::BenchRunsOfShard(spec, manifest.runs, shard).size();
  char host[256] = {};
  if (gethostname(host, sizeof(host) - 1) == 0) manifest.hostname = host;
  manifest.cpus = static_cast<int>(std::thread::hardware_concurrency());
  double load[1] = {0.0};
  if (getloadavg(load, 1) == 1) manifest.load_average = load[0];
  manifest.jobs = args.jobs;
  manifest.started = UtcNow();
  manifest.targets = spec.targets;

  // Ctrl-C: stop starting runs, drop the ones in flight, write what finished, exit 130. A
  // second Ctrl-C kills at once (the files already written stay whole: atomic writes).
  struct sigaction action {};
  action.sa_handler = OnBenchInterrupt;
  action.sa_flags = SA_RESETHAND;  // No SA_RESTART: a waiting poll() returns at once.
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  const acdplan::Stopwatch started;
  bench::BenchRunOptions options;
  options.runs = manifest.runs;
  options.shard = shard;
  options.jobs = args.jobs;
  options.progress = &std::cerr;
  options.stop = &g_bench_stop;
  options.checkpoint = [&](const std::vector<bench::BenchRecord>& records) {
    bench::BenchManifest partial = manifest;
    partial.wall_s = started.Seconds();
    partial.interrupted = true;  // Until the final write says otherwise.
    bench::WriteBenchRecord(out, partial, records);
  };
  std::fprintf(stderr, "bench %s: %zu cases x %d runs, shard %s: %llu runs, %d in parallel -> %s\n",
               spec.name.c_str(), spec.cases.size(), manifest.runs, args.shard.c_str(),
               static_cast<unsigned long long>(manifest.planned_runs), args.jobs, out.c_str());
  const bench::BenchRunOutcome outcome = bench::RunBench(spec, options);
  manifest.wall_s = outcome.wall_s;
  manifest.interrupted = outcome.interrupted;
  try {
    bench::WriteBenchOutputs(out, manifest, outcome.records);
  } catch (const std::runtime_error& error) {
    throw acdplan::InputError(error.what());
  }
  if (!args.no_plots) acdplan::tools::PlotBench(out, &std::cerr);
  ListOutputs(out);
  if (outcome.interrupted) {
    std::fprintf(stderr, "bench: interrupted: %zu of %llu runs written\n", outcome.records.size(),
                 static_cast<unsigned long long>(outcome.planned));
    return 130;
  }
  return 0;
}

/// `acdplan bench-merge`: joins shard folders into the outputs one unsharded run writes.
int RunBenchMerge(const BenchArguments& args) {
  namespace bench = acdplan::bench;
  bench::BenchManifest manifest;
  std::vector<bench::BenchRecord> records;
  bench::MergeBenchRecords(args.merge_dirs, &manifest, &records);
  const std::string out = args.out.empty() ? "bench-out/" + manifest.name + "-merged" : args.out;
  CheckOutputDir(out);
  try {
    bench::WriteBenchOutputs(out, manifest, records);
  } catch (const std::runtime_error& error) {
    throw acdplan::InputError(error.what());
  }
  if (!args.no_plots) acdplan::tools::PlotBench(out, &std::cerr);
  std::printf("merged %zu runs from %zu folders\n", records.size(), args.merge_dirs.size());
  ListOutputs(out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"acdplan: approximate convex decomposition for motion planning"};
  app.set_version_flag("--version", std::string("acdplan ") + ACDPLAN_VERSION);
  app.require_subcommand(1);

  DecomposeArguments args;
  CLI::App* decompose = app.add_subcommand(
      "decompose",
      "Decompose the polygons (dissertation Ch. IV) or the mesh (Ch. V) of INPUT into "
      "tau-convex components and print a summary. Exit status: 0 ok, 2 bad input or usage, 1 "
      "internal error.");
  InputKindOptions kinds;
  decompose
      ->add_option("INPUT", args.input,
                   "Polygon file: .poly, .wkt, .geojson, .json, .shp (ESRI shapefile), .gpkg "
                   "(a GeoPackage; FILE.gpkg|layername=NAME for one of several layers), .kml or "
                   ".kmz; "
                   "or mesh file: .obj, .stl, .ply, .off, .gltf, .glb, .dae or another format "
                   "assimp reads")
      ->required();
  CLI::Option* tau = decompose->add_option(
      "--tau", args.tau,
      "Concavity tolerated per component [input units]; default: polygons 0 (convex), meshes "
      "--tau-rel 0.05");
  kinds.tau = tau;
  const CLI::Validator non_negative = NumberThat([](double x) { return x >= 0; }, "a number >= 0");
  tau->check(non_negative);
  CLI::Option* tau_rel = decompose->add_option(
      "--tau-rel", args.tau_rel,
      "tau relative to the reference radius: polygons, the largest distance from the vertex "
      "mean to a vertex of the outer boundary (with several polygons in INPUT, the largest "
      "radius); meshes, the radius of the minimum enclosing sphere");
  tau_rel->check(non_negative);
  tau->excludes(tau_rel);
  tau_rel->excludes(tau);
  kinds.polygons_only.push_back(
      decompose
          ->add_option("--measure", args.measure, "Polygons: concavity measure: sl, sp, h1 or h2")
          ->capture_default_str()
          ->check(ParsedBy(acd::ParseConcavityMeasure)));
  kinds.polygons_only.push_back(
      decompose
          ->add_option("--min-convexity", args.min_convexity,
                       "Polygons, in (0, 1]: shape decomposition (Algorithm 9), accept a piece "
                       "once area / hull area >= this, instead of the concavity test")
          ->check(NumberThat([](double x) { return x > 0 && x <= 1; }, "a number in (0, 1]")));
  kinds.polygons_only.push_back(
      decompose
          ->add_option("--hole-diameter", args.hole_diameter,
                       "Polygons: hole antipodes: auto, pa (principal axis) or geodesic")
          ->capture_default_str()
          ->check(ParsedBy(acd::ParseHoleDiameter)));
  kinds.polygons_only.push_back(
      decompose->add_flag("--no-steiner", args.no_steiner,
                          "Polygons: cuts end at vertices only (no new vertex on an edge)"));
  kinds.meshes_only.push_back(
      decompose->add_flag("--surface", args.surface,
                          "Meshes: the surface ACD (nearly convex patches of the surface) even "
                          "for a solid; open meshes always get it"));
  kinds.meshes_only.push_back(
      decompose
          ->add_option("--max-hulls", args.max_hulls,
                       "Meshes: then merge the adjacent components whose merged hull adds the "
                       "least volume until at most N remain (they may exceed tau); 0: no cap")
          ->check(CLI::NonNegativeNumber));
  kinds.merge_growth = decompose->add_option(
      "--merge-growth", args.merge_growth,
      "Meshes, solid ACD: after the cuts, merge neighbours whose union is still tau-convex while "
      "their hull grows by at most this fraction (default: tau_rel / 2; a large value: fewest "
      "parts; < 0: no merging)");
  kinds.meshes_only.push_back(kinds.merge_growth);
  decompose->add_option("--json", args.json_path, "Write the decomposition JSON here");
  kinds.polygons_only.push_back(decompose->add_option(
      "--geojson", args.geojson_path,
      "Polygons: write the components as a GeoJSON polygon layer here, each with the attributes "
      "of its input feature (GeoJSON properties, a shapefile's .dbf row)"));
  kinds.polygons_only.push_back(decompose->add_option(
      "--openings-geojson", args.openings_geojson_path,
      "Polygons: write the openings between components as a GeoJSON line layer here (the "
      "passages; each names the two components it joins)"));
  decompose->add_option("--svg", args.svg_path,
                        "Write an SVG picture here (meshes: a shaded oblique view)");
  kinds.meshes_only.push_back(decompose->add_option(
      "--obj", args.obj_path,
      "Meshes: write the components and their hulls as OBJ objects here, materials in the "
      ".mtl file beside it"));
  kinds.meshes_only.push_back(decompose->add_option(
      "--glb", args.glb_path, "Meshes: write the components and their hulls as binary glTF here"));
  decompose->add_flag("--repair", args.repair,
                      "Polygons: make invalid polygons valid (even-odd rule) instead of "
                      "rejecting them, each change printed on stderr. Meshes: close holes and "
                      "remove self-intersections before the solid ACD, each change reported");
  decompose->add_flag("--check", args.check,
                      "Check the result (coverage, disjointness, concavity); on failure "
                      "list the problems, write nothing and exit 1");

  acdplan::bench::BenchCollisionOptions bench_options;
  bench_options.mesh_dir = kDefaultMeshDir;
  std::string bench_json, bench_targets;
  CLI::App* bench_collision = app.add_subcommand(
      "bench-collision",
      "Collision checks per second for bvh, hulls and hulls+exact and point location exact vs "
      "hulls, on the built-in 2D worlds and the meshes of --mesh-dir (bench/collision_bench.h)");
  bench_collision->add_option("--json", bench_json, "Write the results as JSON here");
  bench_collision->add_option("--targets", bench_targets,
                              "YAML file of targets to check (e.g. "
                              "configs/bench/collision_targets.yaml; bench/targets.h)");
  bench_collision->add_option("--poses", bench_options.poses, "Random poses per world and robot")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  bench_collision->add_option("--points", bench_options.points, "Random points per world")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  bench_collision->add_option("--seed", bench_options.seed, "Seed of worlds and poses")
      ->capture_default_str();
  bench_collision
      ->add_option("--tau-rel-3d", bench_options.tau_rel_3d,
                   "3D obstacle ACD tau relative to each obstacle part's reference radius")
      ->capture_default_str()
      ->check(CLI::Range(1e-9, 1e6));
  bench_collision
      ->add_option("--mesh-dir", bench_options.mesh_dir,
                   "Folder of .obj meshes used as 3D obstacles (relative to the working "
                   "directory); '' to skip 3D")
      ->capture_default_str();
  bench_collision
      ->add_option("--meshes", bench_options.meshes,
                   "File names in --mesh-dir to run, comma-separated (e.g. torus1.obj,cup.obj); "
                   "default: every .obj there")
      ->delimiter(',');

  PlanArguments plan_args;
  CLI::App* plan = app.add_subcommand(
      "plan",
      "Plan the scenario of SCENARIO.yaml (planning/scenario.h), an OMPL.app problem "
      "SCENARIO.cfg (planning/scenario_cfg.h), or problem K of a Moving AI benchmark "
      "SCENARIO.scen (--problem K), with an OMPL planner and a "
      "sampler (acd: around the ACD's centroids and openings, Algorithm 10) and print a "
      "summary. Exit status: 0 solved, 3 no solution within the budget, 2 bad input or usage, "
      "1 internal error.");
  plan->add_option("SCENARIO", plan_args.scenario,
                   "Scenario YAML file, OMPL.app problem file (.cfg), or Moving AI scenario "
                   "file (.scen)")
      ->required();
  plan->add_option("--problem", plan_args.problem,
                   "With a Moving AI .scen file: plan its problem K (its K-th line of problems, "
                   "counted from 0)")
      ->check(CLI::NonNegativeNumber);
  // The names come from the planning registry's tables, as the scenario validation does.
  plan->add_option("--sampler", plan_args.sampler,
                   "One of: " + acdplan::JoinNames(acdplan::planning::SamplerNames()))
      ->check(ParsedBy(acdplan::planning::ParseSamplerType));
  plan->add_option("--planner", plan_args.planner,
                   "One of: " + acdplan::JoinNames(acdplan::planning::PlannerNames()) +
                       "; a car scenario: " +
                       acdplan::JoinNames(acdplan::planning::control::ControlPlannerNames()));
  plan->add_option("--seed", plan_args.seed, "Seed (samplers and OMPL)")
      ->check(CLI::NonNegativeNumber);
  CLI::Option* plan_time =
      plan->add_option("--time", plan_args.time, "Time budget [s]")->check(CLI::PositiveNumber);
  CLI::Option* plan_samples = plan->add_option("--samples", plan_args.samples,
                                               "Sample budget: a PRM roadmap of exactly N "
                                               "collision-free samples, solved iff start and "
                                               "goal are connected (dissertation Fig. 4)")
                                  ->check(CLI::PositiveNumber);
  plan_time->excludes(plan_samples);
  plan->add_option("--json", plan_args.json_path, "Write the result as JSON here");
  plan->add_option("--svg", plan_args.svg_path,
                   "Write an SVG picture here (2D: top view; 3D: oblique orthographic view)");
  plan->add_option("--obj", plan_args.obj_path,
                   "3D: write the world, the ACD openings and the path as OBJ here (materials "
                   "in the .mtl beside it)");
  plan->add_option("--glb", plan_args.glb_path, "3D: the same scene as binary glTF here");

  acdplan::tools::EnvArguments env_args;
  CLI::App* env = acdplan::tools::AddEnvCommand(&app, &env_args);

  BenchArguments bench_args;
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Run the benchmark BENCH.yaml (bench/spec.h: worlds x robots x samplers x "
      "planners x budgets) and write runs.csv, results.json, summary.md, one OMPL benchmark log "
      "per world and PNG plots into --out. Exit status: 0 done, 130 interrupted (the finished "
      "runs are written), 2 bad input or usage, 1 internal error.");
  bench->add_option("BENCH", bench_args.spec, "Benchmark YAML file")->required();
  bench->add_option("--runs", bench_args.runs, "Runs per case (default: the file's)")
      ->check(CLI::PositiveNumber);
  bench->add_option("--out", bench_args.out, "Output folder (default bench-out/<name>)");
  bench
      ->add_option("--shard", bench_args.shard,
                   "I/N: run only the runs k (global order) with k % N == I - 1; join the "
                   "shards' folders with bench-merge")
      ->capture_default_str()
      ->check(ParsedBy(acdplan::bench::ParseBenchShard));
  bench
      ->add_option("--jobs", bench_args.jobs,
                   "Runs in parallel (child processes); more than free cores inflates times")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  bench->add_flag("--no-plots", bench_args.no_plots, "Skip tools/plot_bench.py");

  CLI::App* bench_merge = app.add_subcommand(
      "bench-merge",
      "Join the output folders of `bench --shard` runs into the files one unsharded run "
      "writes. Exit status: 0 ok, 2 bad input (folders of different benchmarks, a run in two "
      "folders), 1 internal error.");
  bench_merge->add_option("DIR", bench_args.merge_dirs, "Shard output folders")->required();
  bench_merge->add_option("--out", bench_args.out,
                          "Output folder (default bench-out/<name>-merged)");
  bench_merge->add_flag("--no-plots", bench_args.no_plots, "Skip tools/plot_bench.py");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return app.exit(error);  // --help, --version
    }
    std::cerr << "acdplan: error: " << error.what() << "\n";
    return 2;
  }

  try {
    if (decompose->parsed()) return RunDecompose(args, kinds);
    if (plan->parsed()) return RunPlan(plan_args);
    if (env->parsed()) return acdplan::tools::RunEnv(env_args);
    if (bench_collision->parsed())
      return RunBenchCollision(bench_options, bench_json, bench_targets);
    if (bench->parsed()) return RunBench(bench_args);
    if (bench_merge->parsed()) return RunBenchMerge(bench_args);
    return 0;
  } catch (const acdplan::InputError& error) {
    std::cerr << "acdplan: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "acdplan: internal error: " << error.what() << "\n";
    return 1;
  } catch (...) {
    std::cerr << "acdplan: internal error: unknown exception\n";
    return 1;
  }
}
