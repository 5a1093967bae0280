#include "bench/collision_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <random>

#include "base/format.h"
#include "base/input_error.h"
#include "base/json_number.h"
#include "base/random.h"
#include "bench/cell_process.h"
#include "bench/time_runs.h"
#include "collision/collision_world.h"
#include "collision/point_locator.h"
#include "envs/generators.h"
#include "envs/mesh_loader.h"

namespace acdplan::bench {
namespace {

using collision::BuildObstacleSet;
using collision::CollisionMode;
using collision::CollisionWorld;
using collision::LocateMethod;
using collision::ObstacleSet;
using collision::ObstacleSetOptions;
using collision::PointLocator;
using collision::TriangleCount;

/// A mesh's child process is killed after this long (the decomposition, 20,000 poses in three
/// modes and 200,000 points take under a minute on every V-HACD mesh).
constexpr double kMeshTimeoutS = 900;

nlohmann::json RowToJson(const BenchCollisionRow& r) {
  auto number = [](double x) { return JsonNumber(x); };
  nlohmann::json w;
  w["world"] = r.world;
  w["hulls_source"] = r.hulls_source;
  w["triangles"] = r.triangles;
  w["hulls"] = r.hulls;
  w["poses"] = r.poses;
  w["bvh_checks_per_s"] = number(r.bvh_checks_per_s);
  w["hulls_checks_per_s"] = number(r.hulls_checks_per_s);
  w["hulls_exact_checks_per_s"] = number(r.hulls_exact_checks_per_s);
  w["collision_rate"] = number(r.collision_rate);
  w["hulls_false_positive_rate"] = number(r.hulls_false_positive_rate);
  w["hulls_misses"] = r.hulls_misses;
  w["hulls_exact_mismatches"] = r.hulls_exact_mismatches;
  w["locate_exact_points_per_s"] = number(r.locate_exact_points_per_s);
  w["locate_hulls_points_per_s"] = number(r.locate_hulls_points_per_s);
  w["locate_hulls_error_rate"] = number(r.locate_hulls_error_rate);
  if (!r.note.empty()) w["note"] = r.note;
  return w;
}

BenchCollisionRow RowFromJson(const nlohmann::json& w) {
  auto number = [](const nlohmann::json& x) {
    return x.is_number() ? x.get<double>() : std::nan("");
  };
  BenchCollisionRow r;
  r.world = w["world"].get<std::string>();
  r.hulls_source = w["hulls_source"].get<std::string>();
  r.triangles = w["triangles"].get<int>();
  r.hulls = w["hulls"].get<int>();
  r.poses = w["poses"].get<int>();
  r.bvh_checks_per_s = number(w["bvh_checks_per_s"]);
  r.hulls_checks_per_s = number(w["hulls_checks_per_s"]);
  r.hulls_exact_checks_per_s = number(w["hulls_exact_checks_per_s"]);
  r.collision_rate = number(w["collision_rate"]);
  r.hulls_false_positive_rate = number(w["hulls_false_positive_rate"]);
  r.hulls_misses = w["hulls_misses"].get<int>();
  r.hulls_exact_mismatches = w["hulls_exact_mismatches"].get<int>();
  r.locate_exact_points_per_s = number(w["locate_exact_points_per_s"]);
  r.locate_hulls_points_per_s = number(w["locate_hulls_points_per_s"]);
  r.locate_hulls_error_rate = number(w["locate_hulls_error_rate"]);
  if (w.contains("note")) r.note = w["note"].get<std::string>();
  return r;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Each rate is `count` queries over the median time of up to kPasses passes over all of them
// (at least 3 once a pass set has used kPassBudgetMs): a single pass of a few milliseconds
// varied by +-30% between runs on the shared machine.
constexpr int kPasses = 7;
constexpr double kPassBudgetMs = 1500;

template <typename Pass>
double PerSecond(size_t count, Pass&& pass) {
  const auto timed = TimeRuns(
      [&pass] {
        pass();
        return 0;
      },
      kPasses, kPassBudgetMs, 3);
  return static_cast<double>(count) / (timed.median_ms / 1000);
}

template <class Pose>
void TimeModes(const CollisionWorld& world, const std::vector<Pose>& poses,
               BenchCollisionRow* row) {
  std::vector<char> bvh(poses.size()), hulls(poses.size()), exact(poses.size());
  auto run = [&](CollisionMode mode, std::vector<char>* out) {
    return PerSecond(poses.size(), [&] {
      for (size_t i = 0; i < poses.size(); ++i) (*out)[i] = world.IsValid(poses[i], mode);
    });
  };
  row->poses = static_cast<int>(poses.size());
  row->bvh_checks_per_s = run(CollisionMode::kBvh, &bvh);
  row->hulls_checks_per_s = run(CollisionMode::kHulls, &hulls);
  row->hulls_exact_checks_per_s = run(CollisionMode::kHullsExact, &exact);
  int free = 0, rejected = 0, collisions = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    collisions += !bvh[i];
    free += bvh[i];
    rejected += bvh[i] && !hulls[i];
    row->hulls_misses += hulls[i] && !bvh[i];
    row->hulls_exact_mismatches += exact[i] != bvh[i];
  }
  row->collision_rate = static_cast<double>(collisions) / static_cast<double>(poses.size());
  row->hulls_false_positive_rate = free > 0 ? static_cast<double>(rejected) / free : 0.0;
}

// Fills the locate_* fields; exact may be unavailable (open mesh): NaN and a note.
void TimeLocation(const std::shared_ptr<const ObstacleSet>& set,
                  const std::vector<Eigen::Vector3d>& points, BenchCollisionRow* row) {
  const PointLocator hulls(set, LocateMethod::kHulls);
  std::vector<char> h(points.size()), e(points.size());
  row->locate_hulls_points_per_s = PerSecond(points.size(), [&] { hulls.Inside(points, &h); });
  std::unique_ptr<PointLocator> exact;
  try {
    exact = std::make_unique<PointLocator>(set, LocateMethod::kExact);
  } catch (const InputError& error) {
    row->locate_exact_points_per_s = kNaN;
    row->locate_hulls_error_rate = kNaN;
    row->note = error.what();
    return;
  }
  row->locate_exact_points_per_s = PerSecond(points.size(), [&] { exact->Inside(points, &e); });
  int wrong = 0;
  for (size_t i = 0; i < points.size(); ++i) wrong += h[i] != e[i];
  row->locate_hulls_error_rate = static_cast<double>(wrong) / static_cast<double>(points.size());
}

/// A uniform point of `box` (coordinates drawn in x, y, z order).
template <int N>
Eigen::Matrix<double, N, 1> UniformPoint(const Eigen::AlignedBox<double, N>& box,
                                         RandomEngine& rng) {
  Eigen::Matrix<double, N, 1> p;
  for (int k = 0; k < N; ++k) p[k] = UniformReal(rng, box.min()[k], box.max()[k]);
  return p;
}

std::vector<Eigen::Vector3d> RandomPoints(const Eigen::AlignedBox3d& box, int count, bool flat,
                                          RandomEngine& rng) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    Eigen::Vector3d p = UniformPoint(box, rng);
    if (flat) p.z() = 0;
    points.push_back(p);
  }
  return points;
}

/// A table figure with `decimals` decimals; "n/a" when it could not be measured.
std::string Fixed(double value, int decimals) {
  return std::isnan(value) ? "n/a" : FormatFixed(value, decimals);
}

std::string Percent(double rate) {
  return std::isnan(rate) ? "n/a" : FormatFixed(100 * rate, 2) + "%";
}

}  // namespace

std::vector<BenchCollisionRow> BenchCollision(const BenchCollisionOptions& options,
                                              std::ostream* progress) {
  if (options.poses <= 0 || options.points <= 0) {
    throw InputError("BenchCollision(): poses and points must be > 0");
  }
  std::vector<std::string> mesh_files;
  if (!options.mesh_dir.empty()) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::is_directory(options.mesh_dir, error)) {
      throw InputError("BenchCollision(): " + options.mesh_dir + ": not a folder");
    }
    if (options.meshes.empty()) {
      for (const auto& entry : fs::directory_iterator(options.mesh_dir)) {
        if (entry.path().extension() == ".obj") mesh_files.push_back(entry.path().filename());
      }
      std::sort(mesh_files.begin(), mesh_files.end());
    } else {
      mesh_files = options.meshes;
    }
  }

  std::vector<BenchCollisionRow> rows;
  RandomEngine rng(options.seed);
  ObstacleSetOptions set_options;
  set_options.tau = options.tau;
  set_options.tau_rel_3d = options.tau_rel_3d;

  for (const std::string& name : envs::GeneratorNames()) {
    const envs::Workspace2d workspace = envs::GenerateWorkspace2d(name, options.seed);
    auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace, set_options));
    std::vector<Eigen::Isometry2d> poses;
    for (int i = 0; i < options.poses; ++i) {
      Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
      pose.translation() = UniformPoint(workspace.bounds, rng);
      pose.linear() = Eigen::Rotation2Dd(UniformReal(rng, -M_PI, M_PI)).toRotationMatrix();
      poses.push_back(pose);
    }
    BenchCollisionRow location;
    TimeLocation(set, RandomPoints(set->bounds, options.points, true, rng), &location);
    acd::Polygon2d outline;
    outline.outer = {{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.0}, {-0.1, 0.0}, {-0.1, 0.2}, {-0.3, 0.2}};
    for (const envs::Robot& robot : {envs::Robot::Disc(0.2), envs::Robot::Polygon(outline)}) {
      BenchCollisionRow row = location;
      row.world = name + "/" + ToString(robot.shape);
      row.hulls_source = set->hulls_source;
      row.triangles = TriangleCount(*set);
      row.hulls = static_cast<int>(set->pieces.size());
      const CollisionWorld world(set, robot);
      TimeModes(world, poses, &row);
      if (progress) *progress << "bench-collision: " << row.world << " done\n" << std::flush;
      rows.push_back(row);
    }
  }

  // Each mesh in a child process of its own (bench/cell_process.h), with its own seed: a mesh
  // whose decomposition crashes or hangs is a row with a note, and the others still run (and
  // draw the same poses as without it).
  for (size_t m = 0; m < mesh_files.size(); ++m) {
    const std::string& file = mesh_files[m];
    BenchCollisionRow row;
    row.world = std::filesystem::path(file).stem().string() + "/mesh";
    const std::string path = (std::filesystem::path(options.mesh_dir) / file).string();
    auto work = [&]() {
      RandomEngine mesh_rng(DeriveSeed(options.seed, m));
      envs::Workspace3d workspace;
      workspace.obstacles.push_back(envs::ReadMesh(path));
      const Eigen::AlignedBox3d box = acd::BoundingBox(workspace.obstacles[0]);
      workspace.bounds =
          Eigen::AlignedBox3d(box.min() - 0.1 * box.sizes(), box.max() + 0.1 * box.sizes());
      auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace, set_options));
      BenchCollisionRow measured = row;
      measured.hulls_source = set->hulls_source;
      measured.triangles = TriangleCount(*set);
      measured.hulls = static_cast<int>(set->pieces.size());
      std::vector<Eigen::Isometry3d> poses;
      for (int i = 0; i < options.poses; ++i) {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = UniformPoint(workspace.bounds, mesh_rng);
        // A uniform rotation: a normalised 4D Gaussian (drawn w, x, y, z in order).
        Eigen::Vector4d q;
        for (int k = 0; k < 4; ++k) q[k] = StandardNormal(mesh_rng);
        pose.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
        poses.push_back(pose);
      }
      const CollisionWorld world(set, envs::Robot::Mesh(acd::Cube(0.05 * box.sizes().norm())));
      TimeModes(world, poses, &measured);
      TimeLocation(set, RandomPoints(workspace.bounds, options.points, false, mesh_rng), &measured);
      return RowToJson(measured).dump();
    };
    const CellOutcome outcome = RunCellProcess(work, kMeshTimeoutS);
    if (outcome.status == CellStatus::kOk) {
      row = RowFromJson(nlohmann::json::parse(outcome.output));
    } else {
      const double nan = std::nan("");
      for (double* figure :
           {&row.bvh_checks_per_s, &row.hulls_checks_per_s, &row.hulls_exact_checks_per_s,
            &row.collision_rate, &row.hulls_false_positive_rate, &row.locate_exact_points_per_s,
            &row.locate_hulls_points_per_s, &row.locate_hulls_error_rate}) {
        *figure = nan;
      }
      row.note = "failed: " + outcome.reason;
    }
    if (progress) {
      *progress << "bench-collision: " << row.world << (row.note.empty() ? " done" : " " + row.note)
                << "\n"
                << std::flush;
    }
    rows.push_back(row);
  }
  return rows;
}

namespace {

/// The numeric fields of a row, by their JSON names.
std::vector<std::pair<std::string, double>> Metrics(const BenchCollisionRow& r) {
  return {{"triangles", r.triangles},
          {"hulls", r.hulls},
          {"poses", r.poses},
          {"bvh_checks_per_s", r.bvh_checks_per_s},
          {"hulls_checks_per_s", r.hulls_checks_per_s},
          {"hulls_exact_checks_per_s", r.hulls_exact_checks_per_s},
          {"collision_rate", r.collision_rate},
          {"hulls_false_positive_rate", r.hulls_false_positive_rate},
          {"hulls_misses", r.hulls_misses},
          {"hulls_exact_mismatches", r.hulls_exact_mismatches},
          {"locate_exact_points_per_s", r.locate_exact_points_per_s},
          {"locate_hulls_points_per_s", r.locate_hulls_points_per_s},
          {"locate_hulls_error_rate", r.locate_hulls_error_rate}};
}

std::string CheckCollisionMetric(const std::string& metric) {
  std::string known;
  for (const auto& [name, value] : Metrics(BenchCollisionRow())) {
    if (name == metric) return "";
    known += (known.empty() ? "" : ", ") + name;
  }
  return "unknown metric '" + metric + "' (expected one of: " + known + ")";
}

}  // namespace

const TargetVocabulary& CollisionTargetVocabulary() {
  static const TargetVocabulary vocabulary{{"world", "kind"}, &CheckCollisionMetric};
  return vocabulary;
}

std::vector<TargetRow> CollisionTargetRows(const std::vector<BenchCollisionRow>& rows) {
  std::vector<TargetRow> out;
  for (const BenchCollisionRow& r : rows) {
    TargetRow row;
    row.labels["world"] = r.world;
    const size_t slash = r.world.rfind('/');
    row.labels["kind"] =
        slash != std::string::npos && r.world.substr(slash) == "/mesh" ? "mesh" : "2d";
    // A mesh whose run failed measured nothing: every target on it misses (NaN), rather than
    // not applying.
    const bool failed = r.note.rfind("failed", 0) == 0;
    for (const auto& [name, value] : Metrics(r)) {
      if (failed) {
        row.metrics[name] = std::nan("");
      } else if (!std::isnan(value)) {
        row.metrics[name] = value;
      }
    }
    out.push_back(row);
  }
  return out;
}

std::string BenchCollisionMarkdown(const std::vector<BenchCollisionRow>& rows,
                                   const std::vector<Target>& targets) {
  std::string out =
      "| world | hulls | bvh checks/s | hulls checks/s | (x bvh) | hulls+exact checks/s | (x bvh) "
      "| hulls FP rate | mismatches | exact pts/s | hull pts/s | (x exact) | hull error |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const BenchCollisionRow& r : rows) {
    out += "| " + r.world + " | " + std::to_string(r.hulls) + " | " + Fixed(r.bvh_checks_per_s, 0) +
           " | " + Fixed(r.hulls_checks_per_s, 0) + " | " +
           Fixed(r.hulls_checks_per_s / r.bvh_checks_per_s, 2) + " | " +
           Fixed(r.hulls_exact_checks_per_s, 0) + " | " +
           Fixed(r.hulls_exact_checks_per_s / r.bvh_checks_per_s, 2) + " | " +
           Percent(r.hulls_false_positive_rate) + " | " + std::to_string(r.hulls_exact_mismatches) +
           " | " + Fixed(r.locate_exact_points_per_s, 0) + " | " +
           Fixed(r.locate_hulls_points_per_s, 0) + " | " +
           Fixed(r.locate_hulls_points_per_s / r.locate_exact_points_per_s, 1) + " | " +
           Percent(r.locate_hulls_error_rate) + " |\n";
  }
  out += "\nn/a: exact point location needs a closed mesh.\n";
  for (const BenchCollisionRow& r : rows) {
    if (r.note.rfind("failed", 0) == 0) out += "\n" + r.world + ": " + r.note + "\n";
  }
  if (!targets.empty()) {
    const std::vector<TargetRow> target_rows = CollisionTargetRows(rows);
    out += "\n## Targets\n\n" + TargetChecksMarkdown(CheckTargets(targets, target_rows), {"world"});
  }
  return out;
}

std::string BenchCollisionJson(const std::vector<BenchCollisionRow>& rows,
                               const BenchCollisionOptions& options) {
  nlohmann::json worlds = nlohmann::json::array();
  for (const BenchCollisionRow& r : rows) worlds.push_back(RowToJson(r));
  nlohmann::json doc;
  doc["format"] = "acdplan.bench_collision/1";
  doc["options"] = {
      {"poses", options.poses}, {"points", options.points},         {"seed", options.seed},
      {"tau", options.tau},     {"tau_rel_3d", options.tau_rel_3d}, {"mesh_dir", options.mesh_dir}};
  doc["worlds"] = worlds;
  return doc.dump(2) + "\n";
}

}  // namespace acdplan::bench
